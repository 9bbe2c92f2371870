#pragma once
/** Everything a mission reads from its configuration (config/mission_sim.ini, docs/mission.md):
 * the world, the target, the route, the navigation mode, the search stations, the devices and the
 * files of the robot's models. Relative file names are resolved against the mission file's
 * folder. Every key is checked before anything moves; errors name file, section and key. */
#include <mrolr/arm/GraspChain.h>
#include <mrolr/arm/GraspFeasibility.h>
#include <mrolr/arm/RtxOptions.h>
#include <mrolr/base/LabmateModel.h>
#include <mrolr/base/TrajectoryPlanner.h>
#include <mrolr/geometry/BiSightOptions.h>
#include <mrolr/mission/DeviceOptions.h>
#include <mrolr/mission/ObstacleOptions.h>
#include <mrolr/recog/ImageVerifier.h>
#include <mrolr/recog/RecognitionOptions.h>
#include <mrolr/sim/SimArm.h>
#include <mrolr/sim/SimBase.h>
#include <mrolr/slam/SlamOptions.h>
#include <mrolr/stereo/SceneReconstruction.h>
#include <mrolr/vision/VisionOptions.h>
#include <mrolr/world/World.h>

#include <mrpt/config/CConfigFileBase.h>

#include <Eigen/Core>
#include <iosfwd>
#include <string>
#include <vector>

namespace mrolr::mission
{
enum class NavigationMode
{
	Slam,          ///< active-vision EKF-SLAM (thesis 5.4–5.7)
	DeadReckoning  ///< wheel odometry only
};

/** A named vehicle pose (z, x in m, φ in rad) in W: a waypoint or a search station. */
struct NamedPose
{
	std::string name;
	Eigen::Vector3d xv_zxphi = Eigen::Vector3d::Zero();
};

/** Section [navigation]: the simulated head's landmark measurements (ideal-head angles of eq
 * 5.40 plus Gaussian noise) and the waypoint tolerances. */
struct NavigationOptions
{
	int measurements_per_step = 2;  ///< features measured after each motion step
	int min_mapped_visible = 3;     ///< a new feature is initialised while fewer are visible
	double max_range_m = 8;
	double true_std_pan_rad = 0.002, true_std_elevation_rad = 0.01, true_std_vergence_rad = 0.002;
	double measurement_time_s = 1.0;     ///< simulated time per measurement (saccade + search)
	double waypoint_tolerance_m = 0.03;  ///< correction legs until the estimate is this close
	int max_correction_legs = 3;
	double table_clearance_m = 0.45;  ///< distance kept from a table edge when going round it
	/** Optional: rotations in place are split into steps of at most this (deg), with measurements
	 * after each, so mapped features keep the heading through a turn; 0: the labmate file's
	 * [trajectory] max_rotation_step_deg. */
	double max_rotation_step_deg = 0;
	/** Optional: a goal behind the robot closer than this (m) is reached by driving backwards
	 * (the head keeps facing the features it mapped) instead of turning round; 0: never. */
	double reverse_max_m = 0;
	/** Optional: where the landmark measurements come from. `ideal` (default): the ideal-head
	 * angles (eq 5.40) of the true pose plus Gaussian noise (true_std_*). `images`: the vision
	 * area's cycle (vision::VisualSlam) on the head's stereo pairs: features acquired and fixated
	 * in the images, saved patches sought by NSSD in their innovation ellipses, triangulated
	 * (needs `[files] vision_file`, whose [vision] and [slam] replace the slam_file's filter). */
	std::string measurement_source = "ideal";
	/** Optional, images only: replaces the vision file's [vision] nssd_ambiguity_margin (a match
	 * with a rival within this NSSD elsewhere in its search ellipse is refused); < 0 (default):
	 * the vision file's value. */
	double image_nssd_ambiguity_margin = -1;
	/** Optional, ideal only (reliability check): probability that a chosen feature is lost
	 * (occluded, moved, not found where predicted); the failed attempt counts towards the
	 * deletion rule of 5.7 (more than half of the last ten failed: deleted, known features
	 * kept) and new features are initialised as usual. 0 (default): features are never lost. */
	double lost_feature_probability = 0;
	void loadFromConfigFile(const mrpt::config::CConfigFileBase& cfg, const std::string& section);
	void dump(std::ostream& out) const;
};

/** Section [search]: the pan sweep at a station (thesis 7.2.2) and the simulated scene
 * wire-frame sensor's imperfections (mm). */
struct SearchOptions
{
	double gaze_tilt_deg = -20;  ///< tilt while searching (negative: down)
	double pan_from_deg = -20, pan_to_deg = 20, pan_step_deg = 10;
	double head_move_time_s = 1.0;  ///< simulated time per sweep position (move + grab)
	double endpoint_sigma_mm = 1.0;
	double missing_fraction = 0.15;
	double fragment_probability = 0.1;
	bool hide_back_side = true;
	double max_object_range_m = 2.0;  ///< objects further from C0 are not reconstructed
	/** Render each view's stereo pair into the rawlog (sim::StereoRenderer). */
	bool render_stereo = true;
	/** Where a view's scene wire-frame comes from (optional key, default simulated): `simulated`
	 * (exact object wire-frames, corrupted) or `reconstructed` (stereo::reconstructScene on the
	 * view's rendered pair, options [scene] of `[files] scene_file`). */
	std::string scene_source = "simulated";
	/** Optional, used with scene_source = reconstructed: the recogniser also verifies in the
	 * view's stereo images (recog::ImageVerifier, [image_verification] of recognition_file). */
	bool image_verification = true;
	void loadFromConfigFile(const mrpt::config::CConfigFileBase& cfg, const std::string& section);
	void dump(std::ostream& out) const;
};

/** Section [retrieval]: the reach, verification and carry motions (mm) and simulated times. */
struct RetrievalOptions
{
	double approach_mm = 100;         ///< pre-grasp stand-off along the approach axis z_G
	double lift_mm = 120;             ///< lift after closing the gripper
	double arm_move_time_s = 3.0;     ///< simulated time per arm move
	bool visual_verification = true;  ///< re-observe and correct before closing (beyond 7.2.2)
	/** 0: only the model's grasp line; > 0: if it is infeasible, also the grasp turned about O's
	 * vertical axis in steps of this (for objects symmetric about it), smallest turn first. */
	double grasp_yaw_search_deg = 0;
	/** Optional: a verification grasp further than this from the first is refused (the first is
	 * kept and the report says why): a wrong re-recognition must not throw the arm about. */
	double max_grasp_correction_mm = 40;
	/** Optional, for tests: the first recognised pose is moved this far along C0's x (left)
	 * before the grasp is planned, so the verification has a known error to correct. */
	double inject_pose_error_mm = 0;
	void loadFromConfigFile(const mrpt::config::CConfigFileBase& cfg, const std::string& section);
	void dump(std::ostream& out) const;
};

/** The whole mission configuration. */
struct MissionOptions
{
	std::string config_path;       ///< the mission file itself
	std::string name = "mission";  ///< [mission] name: used in the output folder name
	std::string world_file;        ///< resolved path of maps/<world>/world.ini
	world::World world;            ///< as loaded from world_file
	std::string target;  ///< model to fetch, datasets/objects/<target>.ini (default: the model of
	                     ///< the world's mission target)
	std::string target_model_file;    ///< resolved object definition of the target
	std::vector<std::string> route;   ///< waypoint names driven before searching ("world" = all)
	std::string home_waypoint;        ///< default: the world's home waypoint
	std::vector<NamedPose> stations;  ///< search stations in order (names or "z x phi_deg")
	NavigationMode mode = NavigationMode::Slam;
	bool obstacle_mode = false;  ///< look for obstacles before each step (thesis 5.8.1.2)
	unsigned seed = 1;
	double home_tolerance_m = 0.10;  ///< returned_home when the true pose is this close

	base::LabmateOptions labmate;
	base::TrajectoryOptions trajectory;
	geometry::BiSightOptions bisight;
	slam::SlamOptions slam;
	recog::RecognitionOptions recognition = recog::RecognitionOptions::defaults();
	arm::RtxOptions rtx;
	arm::GraspFeasibilityOptions grasp;
	arm::ArmMount dock;     ///< known T_C0inA of the simulated docking (section [arm_mount])
	DeviceOptions devices;  ///< [device.base|head|arm]: sim or serial (and the serial links)
	sim::SimBaseOptions sim_base;
	sim::SimArmOptions sim_arm;
	NavigationOptions navigation;
	SearchOptions search;
	RetrievalOptions retrieval;
	ObstacleOptions obstacle;  ///< [obstacle], read only when obstacle_mode is set
	/** [image_verification] of [files] recognition_file, read for scene_source = reconstructed
	 * with search.image_verification. */
	recog::ImageVerificationOptions image_verification;
	/** [vision] of [files] vision_file, read for measurement_source = images. */
	vision::VisionOptions vision;
	/** [scene] of [files] scene_file, read for scene_source = reconstructed. */
	stereo::SceneOptions scene;

	/** Reads @p path and every file it names; throws util::ConfigError (file, section, key). */
	static MissionOptions load(const std::string& path);
	/** As load(), from an already open configuration (for tests that override keys); relative
	 * file names are resolved against @p base_dir. */
	static MissionOptions fromConfig(const mrpt::config::CConfigFileBase& cfg,
	                                 const std::string& base_dir);
	void dump(std::ostream& out) const;
};

}  // namespace mrolr::mission
