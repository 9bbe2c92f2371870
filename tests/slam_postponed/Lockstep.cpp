#include "Lockstep.h"

#include <mrolr/slam/HeadMeasurement.h>

#include <algorithm>

namespace mrolr::slam::test
{
namespace
{
Eigen::Matrix<double, 3, 6> jacobian(const Eigen::Vector3d& xv, const Eigen::Vector3d& y,
                                     const HeadConstants& head)
{
	const MeasurementJacobians J = measurementJacobians(xv, y, head);
	Eigen::Matrix<double, 3, 6> H;
	H << J.H_xv, J.H_y;
	return H;
}

Eigen::Vector3d innovation(const Eigen::Vector3d& z, const Eigen::Vector3d& xv,
                           const Eigen::Vector3d& y, const HeadConstants& head)
{
	return measurementDifference(z, predictMeasurement(xv, y, head));
}

Eigen::VectorXd one(double v)
{
	return Eigen::VectorXd::Constant(1, v);
}

}  // namespace

double relativeError(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b)
{
	return (a - b).norm() / b.norm();
}

Lockstep::Lockstep(const ScenarioOptions& options, bool scalar)
    : scenario_(options), scalar_(scalar)
{
	ref_.x = x_ = scenario_.initialState();
	ref_.P = P_ = scenario_.initialCovariance();
	feature_ = scenario_.nextFeature(0);
	steps_left_ = scenario_.trackLength();
	tracker_.start(x_, P_, static_cast<std::size_t>(feature_));
}

void Lockstep::run(int steps)
{
	for (int k = 0; k < steps; ++k)
	{
		if (steps_left_-- == 0) switchFeature();
		step();
	}
	catchUpAndCompare();
}

void Lockstep::step()
{
	predict(scenario_.nextControl());
	const Eigen::Vector3d z = scenario_.measure(feature_);
	if (scalar_)
		updateScalar(z);
	else
		updateBatch(z);
	compareActive();
}

void Lockstep::switchFeature()
{
	catchUpAndCompare();
	feature_ = scenario_.nextFeature(feature_);
	steps_left_ = scenario_.trackLength() - 1;
	tracker_.switchTo(x_, P_, static_cast<std::size_t>(feature_));
	++errors_.switches;
}

void Lockstep::catchUpAndCompare()
{
	tracker_.catchUp(x_, P_);
	errors_.state = std::max(errors_.state, relativeError(x_, ref_.x));
	errors_.covariance = std::max(errors_.covariance, relativeError(P_, ref_.P));
	errors_.asymmetry = std::max(errors_.asymmetry, (P_ - P_.transpose()).cwiseAbs().maxCoeff());
}

void Lockstep::predict(const base::WheelControl& u)
{
	const base::LabmateModel& m = scenario_.model();
	Eigen::Vector3d xv = ref_.vehicle();
	ref_.predict(m.move(xv, u), m.jacobianState(xv, u), m.processNoise(xv, u));
	xv = tracker_.vehicle();
	tracker_.predict(m.move(xv, u), m.jacobianState(xv, u), m.processNoise(xv, u));
}

void Lockstep::updateBatch(const Eigen::Vector3d& z)
{
	const HeadConstants& head = scenario_.head();
	const Eigen::Matrix3d& R = scenario_.measurementNoise();
	Eigen::Vector3d xv = ref_.vehicle(), y = ref_.feature(feature_);
	ref_.update(feature_, innovation(z, xv, y, head), jacobian(xv, y, head), R);
	xv = tracker_.vehicle();
	y = tracker_.feature();
	tracker_.update<3>(innovation(z, xv, y, head), jacobian(xv, y, head), R);
}

void Lockstep::updateScalar(const Eigen::Vector3d& z)
{
	// Each component is linearised at the estimate left by the previous one.
	const HeadConstants& head = scenario_.head();
	const Eigen::Matrix3d& R = scenario_.measurementNoise();
	for (int k = 0; k < 3; ++k)
	{
		Eigen::Vector3d xv = ref_.vehicle(), y = ref_.feature(feature_);
		double nu = innovation(z, xv, y, head)[k];
		ref_.update(feature_, one(nu), jacobian(xv, y, head).row(k), one(R(k, k)).asDiagonal());
		xv = tracker_.vehicle();
		y = tracker_.feature();
		nu = innovation(z, xv, y, head)[k];
		tracker_.updateScalar(nu, jacobian(xv, y, head).row(k), R(k, k));
	}
}

void Lockstep::compareActive()
{
	Eigen::VectorXd x_a(6);
	x_a << ref_.vehicle(), ref_.feature(feature_);
	const std::vector<Eigen::Index> idx{
	    0, 1, 2, 3 + 3 * feature_, 4 + 3 * feature_, 5 + 3 * feature_};
	const Eigen::MatrixXd P_aa = ref_.P(idx, idx);
	errors_.active = std::max({errors_.active, relativeError(tracker_.activeState(), x_a),
	                           relativeError(tracker_.activeCovariance(), P_aa)});
}

}  // namespace mrolr::slam::test
