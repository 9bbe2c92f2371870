#pragma once
// A random EKF-SLAM run for the postponed-update tests: a map of N point features around the start,
// a correlated initial covariance, a true vehicle driven by random wheel controls through the real
// Labmate model (with control noise) and noisy ideal-head measurements of the true features.

#include <mrolr/base/LabmateModel.h>
#include <mrolr/slam/HeadMeasurement.h>

#include <Eigen/Core>

#include <random>

namespace mrolr::slam::test
{
struct ScenarioOptions
{
	int features = 10;  ///< N
	unsigned seed = 1;
	int max_track_steps = 8;  ///< a feature is tracked for 1 … this many steps, then switched
	HeadConstants head;       ///< interocular separation and head height (thesis eqs 5.35, 5.40)
};

/** N features and a seed, the other options at their defaults. */
inline ScenarioOptions scenarioOf(int features, unsigned seed)
{
	ScenarioOptions o;
	o.features = features;
	o.seed = seed;
	return o;
}

class RandomScenario
{
 public:
	explicit RandomScenario(const ScenarioOptions& options);

	const Eigen::VectorXd& initialState() const { return x0_; }
	const Eigen::MatrixXd& initialCovariance() const { return P0_; }
	const base::LabmateModel& model() const { return model_; }
	const Eigen::Matrix3d& measurementNoise() const { return R_; }
	const HeadConstants& head() const { return options_.head; }

	/** A random control; the true vehicle moves by it with control noise. */
	base::WheelControl nextControl();
	/** A noisy measurement z of true feature @p i from the true vehicle. */
	Eigen::Vector3d measure(int i);
	/** A random feature other than @p current (any feature when N = 1). */
	int nextFeature(int current);
	/** A random tracking length in 1 … max_track_steps. */
	int trackLength();

 private:
	double normal(double sigma) { return sigma * std_normal_(rng_); }

	ScenarioOptions options_;
	std::mt19937 rng_;
	std::normal_distribution<double> std_normal_;
	base::LabmateModel model_;
	Eigen::Matrix3d R_;
	Eigen::VectorXd x0_, truth_;
	Eigen::MatrixXd P0_;
};

}  // namespace mrolr::slam::test
