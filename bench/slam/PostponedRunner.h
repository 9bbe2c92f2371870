#pragma once
// The postponed-update path of the benchmark: the full x and P in Eigen storage and a
// PostponedTracker33 tracking one feature, with the same models and measurements as
// BenchKalmanFilter.

#include "BenchProblem.h"

#include <mrolr/slam/PostponedTracker.h>

namespace mrolr::bench
{
class PostponedRunner
{
 public:
	PostponedRunner(BenchProblem& problem, size_t feature);

	/** One tracking step: prediction with the problem's control and a 3-D measurement of the
	 * tracked feature (touches only x_v, y_i, P_aa and the accumulators). */
	void step();
	/** Brings the full x and P up to date (O(N²)). */
	void catchUp() { tracker_.catchUp(x_, P_); }

	const Eigen::VectorXd& state() const { return x_; }

 private:
	BenchProblem& problem_;
	Eigen::VectorXd x_;
	Eigen::MatrixXd P_;
	slam::PostponedTracker33 tracker_;
};

}  // namespace mrolr::bench
