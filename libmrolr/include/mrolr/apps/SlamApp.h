#pragma once
/** `mrolr-slam`: vision-driven EKF-SLAM on a simulated world (thesis 5.2–5.7, 7.2).
 *
 *     mrolr-slam --world maps/lab/world.ini [--config config/slam.ini] --live [--head
 * lab|synthetic]
 *                [--out DIR] [--json]
 *     mrolr-slam --rawlog FILE [--world FILE] [--out DIR] [--json]   (replay of an mrolr-sim run)
 *     mrolr-slam --world maps/lab/world.ini --acquire-known [--known NAME,NAME]
 *
 * The robot drives the world's waypoints (rotate–translate–rotate legs planned from the estimate),
 * its true wheels slipping as configured; at every step the head saccades to the selected feature,
 * finds its saved patch by NSSD in the predicted ellipses and the filter is updated with the
 * triangulated angles. Known features come from <world dir>/known_features.ini when it exists
 * (written by --acquire-known: fixate each known landmark from the first waypoint, lock on, store
 * the patch), otherwise they are acquired the same way at the start of the run. A replay cannot
 * steer the head: it predicts with the recorded odometry and acquires and measures features in the
 * recorded pairs at the recorded head angles (docs/vision.md). */

#include <mrolr/base/LabmateModel.h>
#include <mrolr/base/TrajectoryPlanner.h>
#include <mrolr/geometry/BiSightOptions.h>
#include <mrolr/slam/SlamOptions.h>
#include <mrolr/vision/VisionOptions.h>
#include <mrolr/vision/VisualSlam.h>

#include <mrpt/config/CConfigFileBase.h>

#include <iosfwd>
#include <string>
#include <vector>

namespace mrolr::apps
{
/** Simulation settings of mrolr-slam, section [slam_run] of config/slam.ini. */
struct SlamRunOptions
{
	std::string labmate_config_file = "labmate.ini";  ///< relative to the config file's folder
	std::string bisight_config_file = "bisight.ini";
	unsigned seed = 1;
	double true_velocity_noise_fraction = 0.05;  ///< σ_i = fraction · |v_i| of the true wheels
	double slip_burst_probability = 0.05;        ///< a slip burst starts at a translation step
	int slip_burst_length_steps = 3;
	double slip_fraction = 0.2;   ///< fraction of its distance the left wheel loses in a burst
	double image_noise_grey = 2;  ///< std of the image noise, grey levels
	int texture_size_px = 31;     ///< side of each landmark's texture in the images

	void loadFromConfigFile(const mrpt::config::CConfigFileBase& cfg, const std::string& section);
	void dump(std::ostream& out) const;
};

/** One step of the run (a rawlog frame in replay), for the trajectory CSV. */
struct SlamStepLog
{
	Eigen::Vector3d x_true, x_est, x_dr;  ///< (z, x, φ), metres and radians
	Eigen::Vector3d var_est;              ///< diagonal of the vehicle covariance
	/** What the cycle decided: one record live, one per feature measured in replay. */
	std::vector<vision::CycleRecord> records;
	bool at_home = false;  ///< a known feature re-measured back home (5.6.2), not a route step
};

/** A mapped feature at the end of the run (W: metres, m²). */
struct MapFeature
{
	std::string label;
	bool known = false;
	Eigen::Vector3d p_FinW = Eigen::Vector3d::Zero();
	Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
};

/** A landmark of the world file (ground truth, W, metres), for the 3D scene. */
struct TrueLandmark
{
	std::string name;
	Eigen::Vector3d p_LinW = Eigen::Vector3d::Zero();
};

/** Figures of a run (the --json summary). */
struct SlamSummary
{
	double slam_final_position_error_m = 0, slam_rms_position_m = 0;
	double dr_final_position_error_m = 0, dr_rms_position_m = 0;
	int features = 0, features_added = 0, features_deleted = 0;
	int measurements = 0, matched = 0, accepted = 0;
	double match_success_rate = 0;
	/** Saccades to another feature (5.7) and the measurements they cost: skipped for real with
	 * [vision] selection = saccade, counted only with largest_vs. */
	int saccades = 0, measurements_lost_to_saccades = 0;
	std::string selection;  ///< largest_vs | saccade (live), replay
	int cycles = 0;
	vision::CycleTimes mean_times;  ///< per cycle, ms
};

class SlamApp
{
 public:
	/** Parses the command line; throws util::UsageError for bad arguments. */
	void initialize(const std::vector<std::string>& args);
	/** Runs, writes the outputs, prints a summary (or JSON) to @p out. Returns the exit code. */
	int run(std::ostream& out);

	// Inputs (set by initialize)
	std::string world_path, config_path, rawlog_path, out_dir;
	std::string head_kind = "lab";         ///< --head lab | synthetic
	std::vector<std::string> known_names;  ///< --known: landmarks to acquire as known features
	bool live = false, acquire_known = false, json = false, help_shown = false;

	// Results (set by run)
	std::vector<SlamStepLog> steps;
	std::vector<MapFeature> map;
	std::vector<TrueLandmark> true_landmarks;  ///< the world's, when a world file was given
	SlamSummary summary;
	std::string run_title;  ///< what the run was (live: world, seed, head; replay: rawlog)

 private:
	void runLive();
	void runReplay();
	void recordMap(slam::ActiveSlamFilter& filter, const vision::VisualSlam& vslam);
	void runAcquireKnown(std::ostream& out);
	void writeOutputs() const;
	void printSummary(std::ostream& out) const;
};

}  // namespace mrolr::apps
