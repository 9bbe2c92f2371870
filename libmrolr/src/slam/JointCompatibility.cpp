// Joint compatibility branch and bound over one step's measurements (Neira & Tardós 2001).
#include <mrolr/slam/Chi2.h>
#include <mrolr/slam/JointCompatibility.h>

#include <cmath>

namespace mrolr::slam
{
namespace
{
struct Search
{
	const Eigen::VectorXd& nu;  ///< stacked innovations, 3 per candidate
	const Eigen::MatrixXd& S;   ///< their joint covariance
	double p;
	std::vector<double> gate;  ///< χ²_{3k}(p) for k = 0 … n
	JointCompatibility best;
	bool found = false;

	double nis(const std::vector<size_t>& set) const
	{
		const auto n = static_cast<Eigen::Index>(3 * set.size());
		Eigen::VectorXd v(n);
		Eigen::MatrixXd Ss(n, n);
		for (size_t a = 0; a < set.size(); ++a)
		{
			v.segment<3>(3 * a) = nu.segment<3>(3 * set[a]);
			for (size_t b = 0; b < set.size(); ++b)
				Ss.block<3, 3>(3 * a, 3 * b) = S.block<3, 3>(3 * set[a], 3 * set[b]);
		}
		return v.dot(Ss.ldlt().solve(v));
	}

	void consider(const std::vector<size_t>& set, double d)
	{
		const bool better = !found || set.size() > best.accepted.size() ||
		                    (set.size() == best.accepted.size() && d < best.joint_nis);
		if (better) best = {set, d}, found = true;
	}

	/** Branch on candidate @p i: in (if still jointly compatible) or out. */
	void branch(size_t i, std::vector<size_t>& set, double d)
	{
		const size_t n = gate.size() - 1;
		if (found && set.size() + (n - i) < best.accepted.size()) return;  // cannot do better
		if (i == n)
		{
			consider(set, d);
			return;
		}
		set.push_back(i);
		if (const double with = nis(set); with <= gate[set.size()]) branch(i + 1, set, with);
		set.pop_back();
		branch(i + 1, set, d);
	}
};
}  // namespace

JointCompatibility jointlyCompatible(ActiveSlamFilter& filter,
                                     const std::vector<Observation>& candidates,
                                     double gate_probability)
{
	const size_t n = candidates.size();
	Eigen::VectorXd nu(3 * n);
	std::vector<size_t> features;
	for (size_t k = 0; k < n; ++k)
	{
		Eigen::Vector3d v = candidates[k].h - filter.predictedMeasurement(candidates[k].feature);
		v[0] = std::remainder(v[0], 2 * M_PI);
		nu.segment<3>(3 * k) = v;
		features.push_back(candidates[k].feature);
	}
	const Eigen::MatrixXd S = filter.jointInnovationCovariance(features);
	Search s{nu, S, gate_probability, {0.0}, {}, false};
	for (size_t k = 1; k <= n; ++k) s.gate.push_back(chi2Quantile(gate_probability, 3 * k));
	std::vector<size_t> set;
	s.branch(0, set, 0.0);
	return s.best;
}

}  // namespace mrolr::slam
