#pragma once
// The EKF-SLAM problem the update benchmark runs on: N point features on a ring 4–8 m around the
// start, 2–3 m up, a correlated covariance, a vehicle driving a 1.5 m-radius circle by the Labmate
// model and noisy ideal-head measurements (thesis R = diag(4e-6, 1e-4, 4e-6) rad²).

#include <mrolr/base/LabmateModel.h>
#include <mrolr/slam/HeadMeasurement.h>

#include <Eigen/Core>

#include <random>

namespace mrolr::bench
{
struct BenchProblem
{
	explicit BenchProblem(int features, unsigned seed = 1);

	/** The control of every step: an arc of 0.05 m and 0.033 rad in 1 s. */
	base::WheelControl control() const { return {0.06, 0.04, 1.0}; }
	/** A measurement of feature @p i as seen from the estimate (x_v, y_i), plus angle noise. */
	Eigen::Vector3d measure(const Eigen::Vector3d& x_v, const Eigen::Vector3d& y_i);

	int N;
	Eigen::VectorXd x0;  ///< (x_v, y_1 … y_N)
	Eigen::MatrixXd P0;  ///< 1e-2·L Lᵀ/k + 1e-4·I with a random n×k L, k = 20
	Eigen::Matrix3d R;
	base::LabmateModel model;
	slam::HeadConstants head;
	std::mt19937 rng;
	std::normal_distribution<double> normal;
};

}  // namespace mrolr::bench
