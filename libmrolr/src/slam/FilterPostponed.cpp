// ActiveSlamFilter with Davison's postponed update (appendix C): while the same single feature is
// measured step after step, predictions and updates go through the PostponedTracker and touch only
// (x_v, y_i); any other operation first brings x and P up to date (synchronise).
#include <mrolr/base/TrajectoryPlanner.h>
#include <mrolr/slam/ActiveSlamFilter.h>

#include <Eigen/Cholesky>

namespace mrolr::slam
{
bool ActiveSlamFilter::postponedApplies(const std::vector<Observation>& z) const
{
	return m_options.update_method == UpdateMethod::Postponed && z.size() == 1;
}

void ActiveSlamFilter::synchronise()
{
	if (!m_tracker.tracking()) return;
	auto x = m_xkk.asEigen();
	auto P = m_pkk.asEigen();
	m_tracker.stop(x, P);
	m_xkk[2] = base::wrapAngle(m_xkk[2]);
	const Eigen::MatrixXd Ps = 0.5 * (P + P.transpose());
	P = Ps;
}

void ActiveSlamFilter::predictPostponed()
{
	const Eigen::Vector3d xv = m_tracker.vehicle();
	m_tracker.predict(m_model.move(xv, m_u), transitionJacobian(xv), processNoise(xv));
	notePrediction(m_tracker.vehicle());
}

UpdateReport ActiveSlamFilter::updatePostponed(const Observation& z)
{
	if (!m_tracker.tracking() || m_tracker.trackedFeature() != z.feature)
	{
		synchronise();
		const auto x = m_xkk.asEigen();
		const auto P = m_pkk.asEigen();
		m_tracker.start(x, P, z.feature);
	}
	const Eigen::Vector3d xv = m_tracker.vehicle(), y = m_tracker.feature();
	const auto& head = m_options.head.constants;
	const auto J = observationJacobians(z.feature, xv, y);
	Eigen::Matrix<double, 3, 6> H;
	H << J.H_xv, J.H_y;
	const Eigen::Matrix3d R = measurementNoise();
	const Eigen::Matrix3d S = H * m_tracker.activeCovariance() * H.transpose() + R;
	const Eigen::Vector3d nu = measurementDifference(z.h, predictMeasurement(xv, y, head));
	const double nis = nu.dot(S.ldlt().solve(nu));
	UpdateReport report;
	if (!(nis <= m_gate))
	{
		report.rejected.push_back(z.feature);
		report.rejected_nis.push_back(nis);
		return report;
	}
	m_tracker.update<3>(nu, H, R);
	report.accepted.push_back(z.feature);
	report.nis.push_back(nis);
	return report;
}

}  // namespace mrolr::slam
