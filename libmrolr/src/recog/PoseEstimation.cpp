#include <mrolr/recog/PoseEstimation.h>

#include <opengv/point_cloud/PointCloudAdapter.hpp>
#include <opengv/point_cloud/methods.hpp>
#include <opengv/sac/Ransac.hpp>
#include <opengv/sac_problems/point_cloud/PointCloudSacProblem.hpp>

#include <Eigen/Eigenvalues>

namespace mrolr::recog
{
namespace
{
/** Lines closer to parallel than this contribute their perpendicular offset as a direction. */
constexpr double kParallelOffsetAngle = 5.0 * M_PI / 180.0;

/** Horn's symmetric 4×4 matrix of S = sum w a b^T (quaternion order w, x, y, z). */
Eigen::Matrix4d hornMatrix(const Eigen::Matrix3d& S)
{
	Eigen::Matrix4d N;
	const double xx = S(0, 0), xy = S(0, 1), xz = S(0, 2), yx = S(1, 0), yy = S(1, 1), yz = S(1, 2),
	             zx = S(2, 0), zy = S(2, 1), zz = S(2, 2);
	N << xx + yy + zz, yz - zy, zx - xz, xy - yx,  //
	    yz - zy, xx - yy - zz, xy + yx, zx + xz,   //
	    zx - xz, xy + yx, -xx + yy - zz, yz + zy,  //
	    xy - yx, zx + xz, yz + zy, -xx - yy + zz;
	return N;
}

/** A fragment-invariant vector between two features, or zero: conic centre to conic centre,
 * conic centre to the foot of its perpendicular on a line, and the perpendicular offset between
 * near-parallel lines. These fix rotations that the directions alone leave free (coaxial circles,
 * parallel lines). */
Eigen::Vector3d offsetBetween(const Feature& a, const Feature& b)
{
	if (!a.isLine() && !b.isLine()) return b.m - a.m;
	if (a.isLine() && b.isLine())
	{
		if (std::abs(a.u.dot(b.u)) < std::cos(kParallelOffsetAngle)) return Eigen::Vector3d::Zero();
		const Eigen::Vector3d w = b.m - a.m;
		return w - w.dot(a.u) * a.u;
	}
	const Feature& l = a.isLine() ? a : b;
	const Feature& c = a.isLine() ? b : a;
	const Eigen::Vector3d foot = l.m + (c.m - l.m).dot(l.u) * l.u;
	return a.isLine() ? Eigen::Vector3d(c.m - foot) : Eigen::Vector3d(foot - c.m);
}

void addDirections(const std::vector<Correspondence>& cs, std::vector<Eigen::Vector3d>& a,
                   std::vector<Eigen::Vector3d>& b, std::vector<double>& w)
{
	for (const auto& c : cs)
	{
		a.push_back(c.model.u);
		b.push_back(c.scene.u);
		w.push_back(std::min(c.model.len_mm, c.scene.len_mm));
	}
	for (size_t i = 0; i < cs.size(); ++i)
		for (size_t j = i + 1; j < cs.size(); ++j)
		{
			const Eigen::Vector3d dm = offsetBetween(cs[i].model, cs[j].model);
			const Eigen::Vector3d ds = offsetBetween(cs[i].scene, cs[j].scene);
			if (dm.norm() < 1 || ds.norm() < 1) continue;
			a.push_back(dm.normalized());
			b.push_back(ds.normalized());
			w.push_back(dm.norm());
		}
}

std::optional<Eigen::Vector3d> translationFor(const std::vector<Correspondence>& cs,
                                              const Eigen::Matrix3d& R)
{
	Eigen::Matrix3d A = Eigen::Matrix3d::Zero();
	Eigen::Vector3d rhs = Eigen::Vector3d::Zero();
	for (const auto& c : cs)
	{
		const Eigen::Matrix3d P =
		    c.model.isLine()
		        ? Eigen::Matrix3d(Eigen::Matrix3d::Identity() - c.scene.u * c.scene.u.transpose())
		        : Eigen::Matrix3d(Eigen::Matrix3d::Identity());
		A += P;
		rhs += P * (c.scene.m - R * c.model.m);
	}
	// the eigenvalues alone: the same QR steps on the same tridiagonal form, without the vectors
	const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es(A, Eigen::EigenvaluesOnly);
	if (es.eigenvalues()(0) < 1e-3) return std::nullopt;
	return Eigen::Vector3d(A.ldlt().solve(rhs));
}

/** Midpoint of the common perpendicular of two non-parallel lines. */
Eigen::Vector3d commonPerpendicularMidpoint(const Feature& a, const Feature& b)
{
	const Eigen::Vector3d w0 = a.m - b.m;
	const double c = a.u.dot(b.u), d = a.u.dot(w0), e = b.u.dot(w0), den = 1 - c * c;
	const double s = (c * e - d) / den, t = (e - c * d) / den;
	return 0.5 * ((a.m + s * a.u) + (b.m + t * b.u));
}

/** The fragment-invariant point of a feature pair: the common perpendicular's midpoint of lines at
 * least 30° apart, or the foot of the perpendicular from a conic's centre onto a line. @p force
 * computes it even when the pair is not qualified (the scene side of a qualified model pair). */
std::optional<Eigen::Vector3d> pairPoint(const Feature& a, const Feature& b, bool force = false)
{
	if (a.isLine() && b.isLine())
	{
		if (!force && a.u.cross(b.u).norm() < std::sin(30.0 * M_PI / 180.0)) return std::nullopt;
		return commonPerpendicularMidpoint(a, b);
	}
	if (!a.isLine() && !b.isLine()) return std::nullopt;
	const Feature& l = a.isLine() ? a : b;
	const Feature& c = a.isLine() ? b : a;
	return Eigen::Vector3d(l.m + (c.m - l.m).dot(l.u) * l.u);
}

/** True when the points span a plane (second singular value of the centred cloud over 1 mm RMS). */
bool spansPlane(const opengv::points_t& pts)
{
	Eigen::Vector3d mean = Eigen::Vector3d::Zero();
	for (const auto& p : pts) mean += p / static_cast<double>(pts.size());
	Eigen::Matrix3d C = Eigen::Matrix3d::Zero();
	for (const auto& p : pts) C += (p - mean) * (p - mean).transpose();
	const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es(C / static_cast<double>(pts.size()),
	                                                        Eigen::EigenvaluesOnly);
	return es.eigenvalues()(1) > 1.0;
}

Eigen::Isometry3d fromOpengv(const opengv::transformation_t& T)
{
	Eigen::Isometry3d out = Eigen::Isometry3d::Identity();
	out.linear() = T.block<3, 3>(0, 0);
	out.translation() = T.col(3);
	return out;
}
}  // namespace

std::optional<Eigen::Matrix3d> rotationFromDirections(const std::vector<Eigen::Vector3d>& a,
                                                      const std::vector<Eigen::Vector3d>& b,
                                                      const std::vector<double>& w)
{
	Eigen::Matrix3d S = Eigen::Matrix3d::Zero();
	for (size_t i = 0; i < a.size(); ++i) S += w[i] * a[i] * b[i].transpose();
	Eigen::SelfAdjointEigenSolver<Eigen::Matrix4d> es(hornMatrix(S));
	const auto& ev = es.eigenvalues();  // ascending
	const double scale = std::max(std::abs(ev(3)), 1e-12);
	if ((ev(3) - ev(2)) < 1e-6 * scale) return std::nullopt;
	const Eigen::Vector4d q = es.eigenvectors().col(3);
	return Eigen::Quaterniond(q(0), q(1), q(2), q(3)).normalized().toRotationMatrix();
}

std::optional<Eigen::Isometry3d> faugerasHebertPose(const std::vector<Correspondence>& cs)
{
	static thread_local std::vector<Eigen::Vector3d> a, b;  // kept per thread: a pose per clique
	static thread_local std::vector<double> w;
	a.clear(), b.clear(), w.clear();
	addDirections(cs, a, b, w);
	const auto R = rotationFromDirections(a, b, w);
	if (!R) return std::nullopt;
	const auto t = translationFor(cs, *R);
	if (!t) return std::nullopt;
	Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
	T.linear() = *R;
	T.translation() = *t;
	return T;
}

std::vector<std::pair<Eigen::Vector3d, Eigen::Vector3d>> correspondingPoints(
    const std::vector<Correspondence>& cs)
{
	std::vector<std::pair<Eigen::Vector3d, Eigen::Vector3d>> pts;
	for (size_t i = 0; i < cs.size(); ++i)
	{
		if (!cs[i].model.isLine()) pts.push_back({cs[i].model.m, cs[i].scene.m});
		for (size_t j = i + 1; j < cs.size(); ++j)
			if (auto p = pairPoint(cs[i].model, cs[j].model))
				pts.push_back({*p, *pairPoint(cs[i].scene, cs[j].scene, true)});
	}
	return pts;
}

std::optional<Eigen::Isometry3d> arunPose(const std::vector<Correspondence>& cs,
                                          double ransac_threshold_mm)
{
	const auto pts = correspondingPoints(cs);
	if (pts.size() < 3) return std::nullopt;
	opengv::points_t scene, model;
	for (const auto& p : pts)
	{
		model.push_back(p.first);
		scene.push_back(p.second);
	}
	if (!spansPlane(model)) return std::nullopt;
	opengv::point_cloud::PointCloudAdapter adapter(scene, model);
	if (pts.size() < 6) return fromOpengv(opengv::point_cloud::threept_arun(adapter));
	using Problem = opengv::sac_problems::point_cloud::PointCloudSacProblem;
	opengv::sac::Ransac<Problem> ransac(200, ransac_threshold_mm, 0.99);
	ransac.sac_model_ = std::make_shared<Problem>(adapter, false);
	if (!ransac.computeModel()) return std::nullopt;
	return fromOpengv(opengv::point_cloud::threept_arun(adapter, ransac.inliers_));
}

}  // namespace mrolr::recog
