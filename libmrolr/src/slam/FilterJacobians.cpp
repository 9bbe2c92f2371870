// Where ActiveSlamFilter linearises: at the current estimate (standard EKF) or, for FEJ-EKF
// (Huang, Mourikis & Roumeliotis 2008), at the first estimates, which keeps the linearised
// system's unobservable directions (global position and heading) unobservable and the filter
// consistent.
#include <mrolr/slam/ActiveSlamFilter.h>

namespace mrolr::slam
{
Eigen::Matrix3d ActiveSlamFilter::transitionJacobian(const Eigen::Vector3d& x_v) const
{
	if (options_.jacobians == JacobianPoint::Standard) return model_.jacobianState(x_v, u_);
	// FEJ: ∂f/∂φ from the propagated estimates x_{k+1|k} − x_{k|k−1} instead of x_{k+1|k} −
	// x_{k|k}.
	const Eigen::Vector3d d = model_.move(x_v, u_) - xv_prior_;
	Eigen::Matrix3d F = Eigen::Matrix3d::Identity();
	F(0, 2) = -d[1];
	F(1, 2) = d[0];
	return F;
}

MeasurementJacobians ActiveSlamFilter::observationJacobians(size_t i, const Eigen::Vector3d& x_v,
                                                            const Eigen::Vector3d& y) const
{
	const auto& head = options_.head.constants;
	if (options_.jacobians == JacobianPoint::Standard) return measurementJacobians(x_v, y, head);
	// FEJ: the vehicle at its prior x_{k|k−1}, the feature at its first estimate.
	return measurementJacobians(xv_prior_, info_.at(i).p_FinW_first, head);
}

void ActiveSlamFilter::notePrediction(const Eigen::Vector3d& x_v_predicted)
{
	xv_prior_ = x_v_predicted;
}

}  // namespace mrolr::slam
