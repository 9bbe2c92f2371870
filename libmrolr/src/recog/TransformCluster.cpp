#include <mrolr/recog/TransformCluster.h>

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <numeric>

namespace mrolr::recog
{
namespace
{
void computeSpread(PoseCluster& c, const std::vector<PoseHypothesis>& hyps,
                   const Eigen::Vector3d& centroid_O)
{
	double r2 = 0, t2 = 0;
	const Eigen::Vector3d pm = c.mean * centroid_O;
	for (size_t i : c.members)
	{
		r2 += std::pow(rotationDistanceDeg(c.mean.linear(), hyps[i].T_OinS.linear()), 2);
		t2 += (hyps[i].T_OinS * centroid_O - pm).squaredNorm();
	}
	c.spread_rot_deg = std::sqrt(r2 / c.members.size());
	c.spread_trans_mm = std::sqrt(t2 / c.members.size());
}

void finishCluster(PoseCluster& c, const std::vector<PoseHypothesis>& hyps,
                   const Eigen::Vector3d& centroid_O)
{
	std::vector<Eigen::Isometry3d> Ts;
	std::vector<double> w;
	for (size_t i : c.members)
	{
		Ts.push_back(hyps[i].T_OinS);
		w.push_back(hyps[i].weight);
	}
	c.mean = meanTransform(Ts, w);
	computeSpread(c, hyps, centroid_O);
}
}  // namespace

double rotationDistanceDeg(const Eigen::Matrix3d& Ra, const Eigen::Matrix3d& Rb)
{
	return Eigen::AngleAxisd(Ra.transpose() * Rb).angle() * 180.0 / M_PI;
}

Eigen::Isometry3d meanTransform(const std::vector<Eigen::Isometry3d>& Ts,
                                const std::vector<double>& w)
{
	Eigen::Matrix4d M = Eigen::Matrix4d::Zero();
	Eigen::Vector3d t = Eigen::Vector3d::Zero();
	double wsum = 0;
	for (size_t i = 0; i < Ts.size(); ++i)
	{
		const Eigen::Vector4d q = Eigen::Quaterniond(Ts[i].linear()).coeffs();
		M += w[i] * q * q.transpose();
		t += w[i] * Ts[i].translation();
		wsum += w[i];
	}
	Eigen::SelfAdjointEigenSolver<Eigen::Matrix4d> es(M);
	Eigen::Isometry3d out = Eigen::Isometry3d::Identity();
	out.linear() = Eigen::Quaterniond(Eigen::Vector4d(es.eigenvectors().col(3)))
	                   .normalized()
	                   .toRotationMatrix();
	out.translation() = t / wsum;
	return out;
}

std::vector<PoseCluster> clusterTransforms(const std::vector<PoseHypothesis>& hyps,
                                           const Eigen::Vector3d& centroid_O,
                                           double max_rotation_deg, double max_translation_mm,
                                           size_t max_clusters)
{
	std::vector<size_t> order(hyps.size());
	std::iota(order.begin(), order.end(), 0);
	std::stable_sort(order.begin(), order.end(),
	                 [&](size_t a, size_t b) { return hyps[a].weight > hyps[b].weight; });
	// each hypothesis's centroid, worked out once (it is compared with every cluster's)
	std::vector<Eigen::Vector3d> centroid_S;
	centroid_S.reserve(hyps.size());
	for (const auto& h : hyps) centroid_S.push_back(h.T_OinS * centroid_O);
	std::vector<PoseCluster> clusters;
	for (size_t i : order)
	{
		const auto& T = hyps[i].T_OinS;
		// the translation first: it is cheaper, and most clusters fail it
		const auto near = [&](const PoseCluster& c)
		{
			const size_t first = c.members.front();
			return (centroid_S[first] - centroid_S[i]).norm() <= max_translation_mm &&
			       rotationDistanceDeg(hyps[first].T_OinS.linear(), T.linear()) <= max_rotation_deg;
		};
		auto it = std::find_if(clusters.begin(), clusters.end(), near);
		if (it == clusters.end()) it = clusters.insert(clusters.end(), PoseCluster{});
		it->members.push_back(i);
		it->weight += hyps[i].weight;
	}
	// the order is the weights' alone, so the heaviest are known before any mean is
	std::stable_sort(clusters.begin(), clusters.end(),
	                 [](const auto& a, const auto& b) { return a.weight > b.weight; });
	if (clusters.size() > max_clusters) clusters.resize(max_clusters);
	for (auto& c : clusters) finishCluster(c, hyps, centroid_O);
	return clusters;
}

}  // namespace mrolr::recog
