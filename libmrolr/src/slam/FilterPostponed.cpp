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
	return options_.update_method == UpdateMethod::Postponed && z.size() == 1;
}

void ActiveSlamFilter::synchronise()
{
	if (!tracker_.tracking()) return;
	auto x = m_xkk.asEigen();
	auto P = m_pkk.asEigen();
	tracker_.stop(x, P);
	m_xkk[2] = base::wrapAngle(m_xkk[2]);
	const Eigen::MatrixXd Ps = 0.5 * (P + P.transpose());
	P = Ps;
}

void ActiveSlamFilter::predictPostponed()
{
	const Eigen::Vector3d xv = tracker_.vehicle();
	tracker_.predict(model_.move(xv, u_), transitionJacobian(xv), processNoise(xv));
	notePrediction(tracker_.vehicle());
}

UpdateReport ActiveSlamFilter::updatePostponed(const Observation& z)
{
	if (!tracker_.tracking() || tracker_.trackedFeature() != z.feature)
	{
		synchronise();
		const auto x = m_xkk.asEigen();
		const auto P = m_pkk.asEigen();
		tracker_.start(x, P, z.feature);
	}
	const Eigen::Vector3d xv = tracker_.vehicle(), y = tracker_.feature();
	const auto& head = options_.head.constants;
	const auto J = observationJacobians(z.feature, xv, y);
	Eigen::Matrix<double, 3, 6> H;
	H << J.H_xv, J.H_y;
	const Eigen::Matrix3d R = measurementNoise();
	const Eigen::Matrix3d S = H * tracker_.activeCovariance() * H.transpose() + R;
	const Eigen::Vector3d nu = measurementDifference(z.h, predictMeasurement(xv, y, head));
	const double nis = nu.dot(S.ldlt().solve(nu));
	UpdateReport report;
	if (!(nis <= gate_))
	{
		report.rejected.push_back(z.feature);
		report.rejected_nis.push_back(nis);
		return report;
	}
	tracker_.update<3>(nu, H, R);
	report.accepted.push_back(z.feature);
	report.nis.push_back(nis);
	return report;
}

}  // namespace mrolr::slam
