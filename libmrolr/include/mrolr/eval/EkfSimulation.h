#pragma once
/** Simulator module 1 (thesis 6.8) for the active-vision EKF-SLAM: a vehicle drives a world's
 * waypoint route with the rotate–translate–rotate planner (5.6.3, 7.2.1); the true vehicle moves by
 * the noisy Labmate model (plus optional wheel-slip bursts), the head measures the true ideal-head
 * angles plus noise (and occasional outliers) of the feature the filter selects, within the head's
 * limits and the visibility rules; the filter maps and localises (5.7). One run gives per-step
 * truth, estimate and dead reckoning; many runs give the Monte-Carlo consistency figures. The
 * simulated truth and the filter's belief meet here, so the harness lives in eval. */

#include <mrolr/base/LabmateModel.h>
#include <mrolr/base/TrajectoryPlanner.h>
#include <mrolr/slam/SlamOptions.h>
#include <mrolr/world/World.h>

#include <mrpt/config/CConfigFileBase.h>

#include <Eigen/Core>

#include <cstdint>
#include <functional>
#include <iosfwd>
#include <string>
#include <vector>

namespace mrolr::eval
{
/** Section [simulation] of config/ekf_sim.ini. */
struct SimulationOptions
{
	uint64_t seed = 1;
	/** True wheel-velocity noise σ_i = fraction · |v_i| (the filter assumes [labmate]'s fraction).
	 */
	double true_velocity_noise_fraction = 0.14;
	/** True measurement noise (rad); the filter assumes [slam]'s R. */
	double true_std_pan_rad = 0.002;
	double true_std_elevation_rad = 0.01;
	double true_std_vergence_rad = 0.002;
	/** Wheel slip: a burst starts with this probability per step and lasts this many steps; during
	 * a burst one wheel (chosen at random) covers only (1 − slip_fraction) of its commanded
	 * distance. The filter does not model slip. */
	double slip_burst_probability = 0;
	int slip_burst_length_steps = 3;
	double slip_fraction = 0.2;
	/** With this probability a measurement is an outlier: each angle off by ±U(0.5, 1)·magnitude.
	 */
	double outlier_fraction = 0;
	double outlier_magnitude_rad = 0.2;
	int measurements_per_step = 1;  ///< features measured after each motion step
	double max_range_m = 8;         ///< features further away are never found
	double search_pan_deg = 45;     ///< new features are sought at pan +this, 0, −this (5.7)
	double search_window_deg = 30;  ///< half-width of each search direction
	int laps = 1;                   ///< times the route is driven

	void loadFromConfigFile(const mrpt::config::CConfigFileBase& cfg, const std::string& section);
	void dumpToTextStream(std::ostream& out) const;
};

/** Everything a run needs, loaded from one ekf_sim.ini (which names the labmate and head files). */
struct SimulationSetup
{
	SimulationOptions sim;
	slam::SlamOptions slam;
	base::LabmateOptions labmate;
	base::TrajectoryOptions trajectory;

	/** Reads [simulation] and [slam] from @p path, and [labmate], [trajectory] and [bisight] from
	 * the files its keys labmate_config_file and bisight_config_file name (relative to @p path's
	 * folder). Errors name file, section and key. */
	static SimulationSetup load(const std::string& path);
};

/** One step of one run (after the motion and the update). Poses (z, x, φ) in W. */
struct StepRecord
{
	Eigen::Vector3d truth, estimate, dead_reckoning;
	Eigen::Matrix3d P_vv;  ///< vehicle covariance of the estimate
	double nees = 0;       ///< vehicle NEES eᵀ P_vv⁻¹ e (NaN while P_vv is singular)
	int features = 0;      ///< features in the map
	int measured = 0;      ///< measurements accepted this step
};

/** A whole run. */
struct RunResult
{
	std::vector<StepRecord> steps;
	std::vector<double> nis;  ///< NIS of every accepted measurement
	int features_added = 0, features_deleted = 0, outliers_injected = 0, outliers_rejected = 0;
	int measurements_rejected = 0, attempts_failed = 0;
	double landmark_error_sum_m = 0;  ///< over the features mapped at the end
	int landmark_count = 0;
	std::vector<std::string> final_labels;           ///< map at the end: labels,
	std::vector<Eigen::Vector3d> final_positions;    ///< estimated positions
	std::vector<Eigen::Matrix3d> final_covariances;  ///< and covariances
	std::vector<Eigen::Vector3d> controls_odometry;  ///< commanded (v1, v2, dt) per step
	std::vector<std::vector<std::pair<std::string, Eigen::Vector3d>>> measurements;  ///< per step
	double seconds = 0;  ///< wall time of the run
};

/** Runs one simulation with its own random seed. Throws std::invalid_argument for a world with
 * fewer than two waypoints. */
RunResult runSimulation(const world::World& world, const SimulationSetup& setup, uint64_t seed);

/** Monte-Carlo runs: run r of @p runs uses the seed @p seed0 + 1000 r (so a run is the same
 * whatever the number of runs). @p after_run, when set, is called after each run with the number
 * of runs done. Throws as runSimulation. */
std::vector<RunResult> runMonteCarlo(const world::World& world, const SimulationSetup& setup,
                                     int runs, uint64_t seed0,
                                     const std::function<void(int done)>& after_run = {});

/** Monte-Carlo figures over runs (the keys of mrolr-ekf-sim --json): consistency (NEES against its
 * χ² bounds, NIS) and errors against the truth. */
struct MonteCarloSummary
{
	int runs = 0;
	int steps = 0;                    ///< steps common to all runs (the shortest run)
	double nees_lo = 0, nees_hi = 0;  ///< 95 % two-sided bounds of the mean NEES over the runs
	std::vector<double> mean_nees;    ///< per step (NaN where NEES is undefined in every run)
	int nees_steps = 0;               ///< steps where the mean NEES is defined
	double nees_inside_fraction = 0;
	double slam_rms_position_m = 0, slam_final_position_error_m = 0, slam_rms_heading_deg = 0;
	double dr_rms_position_m = 0, dr_final_position_error_m = 0;
	double mean_landmark_error_m = 0, mean_nis = 0;
	int features_added = 0, features_deleted = 0, outliers_rejected = 0, outliers_injected = 0;
	double ms_per_step = 0;
};

MonteCarloSummary summarise(const std::vector<RunResult>& runs);

}  // namespace mrolr::eval
