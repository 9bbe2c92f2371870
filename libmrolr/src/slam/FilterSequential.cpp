// Sequential scalar updates of ActiveSlamFilter (thesis eqs 5.42–5.45).
//
// Written here rather than taken from MRPT 2.5's kfEKFAlaDavison, which computes the innovation
// ν = z − h(x) of an observation once and then applies its three components one after the other
// without correcting them for the state change the earlier components made: after the earlier
// scalar updates ν_j must be z_j − h_j(x⁻) − H_j (x − x⁻). With correlated components (pan and
// vergence both depend on the vehicle and the feature) MRPT's version over-corrects the state while
// P shrinks as if it had not. Linearised once per observation, as here, the scalar updates equal
// the batch update (test FilterUpdate.SequentialEqualsTheBatchUpdate).
#include <mrolr/base/TrajectoryPlanner.h>
#include <mrolr/slam/ActiveSlamFilter.h>

#include <Eigen/Cholesky>

#include <array>

namespace mrolr::slam
{
namespace
{
using Vec6 = Eigen::Matrix<double, 6, 1>;
using Indices = std::array<Eigen::Index, 6>;

/** Indices of the active block (x_v, y_i) in the full state. */
Indices activeIndices(size_t i)
{
	const auto o = static_cast<Eigen::Index>(3 + 3 * i);
	return {0, 1, 2, o, o + 1, o + 2};
}

Vec6 gather(const Eigen::Ref<const Eigen::VectorXd>& v, const Indices& idx)
{
	Vec6 a;
	for (int c = 0; c < 6; ++c) a[c] = v[idx[c]];
	return a;
}

/** One scalar update x ← x + K ν_j, P ← P − K s Kᵀ with K = P h_jᵀ / s (eqs 5.42–5.45). */
template <class DX, class DP>
void scalarUpdate(DX& x, DP& P, const Indices& idx, const Vec6& h_j, double nu_j, double r_j)
{
	Eigen::VectorXd PHt = Eigen::VectorXd::Zero(x.size());
	for (int c = 0; c < 6; ++c) PHt += P.col(idx[c]) * h_j[c];
	const double s = h_j.dot(gather(PHt, idx)) + r_j;
	const Eigen::VectorXd K = PHt / s;
	x += K * nu_j;
	P.noalias() -= K * (s * K.transpose());
}
}  // namespace

ActiveSlamFilter::PriorLinearisation ActiveSlamFilter::linearisePrior(const Observation& z) const
{
	PriorLinearisation l;
	l.feature = z.feature;
	const Indices idx = activeIndices(z.feature);
	l.a0 = gather(m_xkk.asEigen(), idx);
	const auto J = observationJacobians(z.feature, l.a0.head<3>(), l.a0.tail<3>());
	l.H << J.H_xv, J.H_y;
	l.nu = measurementDifference(
	    z.h, predictMeasurement(l.a0.head<3>(), l.a0.tail<3>(), options_.head.constants));
	Eigen::Matrix<double, 6, 6> P_aa;
	const auto P = m_pkk.asEigen();
	for (int r = 0; r < 6; ++r) P_aa.row(r) = gather(P.row(idx[r]).transpose(), idx).transpose();
	l.nis = l.nu.dot((l.H * P_aa * l.H.transpose() + measurementNoise()).ldlt().solve(l.nu));
	return l;
}

void ActiveSlamFilter::applyScalarUpdates(const PriorLinearisation& l)
{
	auto x = m_xkk.asEigen();
	auto P = m_pkk.asEigen();
	const Indices idx = activeIndices(l.feature);
	const Eigen::Vector3d r = measurementNoise().diagonal();
	for (int j = 0; j < 3; ++j)
	{
		// ν_j corrected for what the earlier scalar updates moved (heading difference wrapped).
		Vec6 da = gather(x, idx) - l.a0;
		da[2] = base::wrapAngle(da[2]);
		scalarUpdate(x, P, idx, l.H.row(j).transpose(), l.nu[j] - l.H.row(j).dot(da), r[j]);
	}
	x[2] = base::wrapAngle(x[2]);
}

void ActiveSlamFilter::updateSequential(const std::vector<Observation>& z)
{
	// All observations linearised and gated at the prior, as the batch update does.
	std::vector<PriorLinearisation> accepted;
	for (const auto& o : z)
	{
		const auto l = linearisePrior(o);
		if (!(l.nis <= gate_))
		{
			report_.rejected.push_back(o.feature);
			report_.rejected_nis.push_back(l.nis);
			continue;
		}
		report_.accepted.push_back(o.feature);
		report_.nis.push_back(l.nis);
		accepted.push_back(l);
	}
	for (const auto& l : accepted) applyScalarUpdates(l);
	OnPostIteration();
}

}  // namespace mrolr::slam
