#pragma once
// Runs the postponed tracker and the plain full EKF side by side on one RandomScenario: the same
// controls and measurements, each filter linearising at its own estimate, and records how far the
// tracker's caught-up state is from the reference.

#include "FullEkf.h"
#include "RandomScenario.h"

#include <mrolr/slam/PostponedTracker.h>

#include <Eigen/Core>

namespace mrolr::slam::test
{
/** Largest relative differences seen (Frobenius norm of the difference / norm of the reference). */
struct LockstepErrors
{
	double state = 0;       ///< full x after every catch-up
	double covariance = 0;  ///< full P after every catch-up
	double active = 0;      ///< (x_a, P_aa) after every step
	double asymmetry = 0;   ///< max |P − Pᵀ| after every catch-up
	int switches = 0;
};

class Lockstep
{
 public:
	/** @p scalar: sequential scalar updates (eqs 5.42–5.45) instead of the 3-D batch update. */
	Lockstep(const ScenarioOptions& options, bool scalar);

	/** @p steps predictions and measurements, switching features as the scenario says; ends
	 * with a catch-up. */
	void run(int steps);
	/** One prediction and measurement of the tracked feature, without any catch-up. */
	void step();
	/** Catch up the tracker and compare the full state. */
	void catchUpAndCompare();

	const LockstepErrors& errors() const { return errors_; }
	const FullEkf& reference() const { return ref_; }
	const Eigen::VectorXd& trackerState() const { return x_; }
	const Eigen::MatrixXd& trackerCovariance() const { return P_; }
	int trackedFeature() const { return feature_; }

 private:
	void predict(const base::WheelControl& u);
	void updateBatch(const Eigen::Vector3d& z);
	void updateScalar(const Eigen::Vector3d& z);
	void compareActive();
	void switchFeature();

	RandomScenario scenario_;
	bool scalar_;
	FullEkf ref_;
	Eigen::VectorXd x_;
	Eigen::MatrixXd P_;
	PostponedTracker33 tracker_;
	int feature_ = 0;
	int steps_left_ = 0;
	LockstepErrors errors_;
};

/** (a − b).norm() / b.norm(). */
double relativeError(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b);

}  // namespace mrolr::slam::test
