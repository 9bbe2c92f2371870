#pragma once
/** Everything the robot side reads from its configuration (config/mission_sim.ini,
 * docs/mission.md): its plan (route, stations, home, known features, tables; mission/Plan.h), the
 * target model and the model database, the navigation mode, the devices and its calibration files.
 * Never a world file: that belongs to the simulator (sim::LabOptions). Relative file names are
 * resolved against the mission file's folder. Every key is checked before anything moves; errors
 * name file, section and key. */
#include <mrolr/arm/GraspChain.h>
#include <mrolr/arm/GraspFeasibility.h>
#include <mrolr/arm/RtxOptions.h>
#include <mrolr/base/LabmateModel.h>
#include <mrolr/base/TrajectoryPlanner.h>
#include <mrolr/geometry/BiSightOptions.h>
#include <mrolr/mission/DeviceOptions.h>
#include <mrolr/mission/DockCalibration.h>
#include <mrolr/mission/DockPlanner.h>
#include <mrolr/mission/ObstacleOptions.h>
#include <mrolr/mission/PlaceOptions.h>
#include <mrolr/mission/Plan.h>
#include <mrolr/recog/images/ImageVerifier.h>
#include <mrolr/recog/RecognitionOptions.h>
#include <mrolr/slam/SlamOptions.h>
#include <mrolr/stereo/SceneReconstruction.h>
#include <mrolr/vision/VisionOptions.h>

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

/** Where the robot's landmark measurements come from (`[navigation] landmark_sensor`). */
enum class LandmarkSource
{
	Images,    ///< `images`: features acquired and found in the head's stereo pairs (vision area)
	Simulated  ///< a simulated sensor named in landmark_sensor (hw::LandmarkSensor; tests only)
};

/** Section [navigation]: where the landmark measurements come from and the waypoint tolerances. */
struct NavigationOptions
{
	double measurement_time_s = 1.0;     ///< robot time per measurement (saccade + search)
	double waypoint_tolerance_m = 0.03;  ///< correction legs until the estimate is this close

	// Fixed in code (docs/config.md "Fixed in code"): each value and why.
	/** Features measured after each motion step (docs/mission.md "Navigation"): each costs
	 * measurement_time_s; three is the value every shipped mission was measured with. */
	int measurements_per_step = 3;
	int min_mapped_visible = 3;  ///< a new feature is initialised while fewer are visible
	int max_correction_legs = 3;  ///< correction legs before the robot reports it missed the goal
	/** Kept from a table edge when going round it (half the 0.7 m wide base, plus 0.1 m). */
	double table_clearance_m = 0.45;
	/** Rotations in place are split into steps of at most this (deg), with measurements after
	 * each, so mapped features keep the heading through a turn (without: half-turns ended 20–40°
	 * off, tests/mission/options_test.cpp); 0: the labmate file's [trajectory] value. */
	double max_rotation_step_deg = 45;
	/** A goal behind the robot closer than this (m) is reached by driving backwards (the head
	 * keeps facing the features it mapped) instead of turning round: the lab's last leg (W5 →
	 * home) and correction legs; 0: never. */
	double reverse_max_m = 0.6;
	/** Optional: `images` (default): the vision area's cycle (vision::VisualSlam) on the head's
	 * stereo pairs (needs `[files] vision_file`, whose [vision] and [slam] replace the slam_file's
	 * filter); any other name is a simulated sensor the app must provide (`ideal_sim`: the
	 * ideal-head angles of the world's landmarks, for tests). */
	LandmarkSource landmark_source = LandmarkSource::Images;
	std::string landmark_sensor = "images";  ///< the name as configured
	/** Optional, images only: replaces the vision file's [vision] nssd_ambiguity_margin (a match
	 * with a rival within this NSSD elsewhere in its search ellipse is refused); < 0 (default):
	 * the vision file's value. */
	double image_nssd_ambiguity_margin = -1;
	/** Optional, simulated sensors only (reliability check): probability that a chosen feature is
	 * lost (occluded, moved, not found where predicted); the failed attempt counts towards the
	 * deletion rule of 5.7 (more than half of the last ten failed: deleted, known features kept)
	 * and new features are initialised as usual. 0 (default): features are never lost. */
	double lost_feature_probability = 0;
	void loadFromConfigFile(const mrpt::config::CConfigFileBase& cfg, const std::string& section);
	void dump(std::ostream& out) const;
};

/** Where a view's scene wire-frame comes from (`[search] scene_sensor`). */
enum class SceneSource
{
	Reconstructed,  ///< `reconstructed`: stereo::reconstructScene on the view's stereo pair
	Simulated       ///< a simulated sensor named in scene_sensor (hw::SceneSensor; tests only)
};

/** Section [search]: the pan sweep at a station (thesis 7.2.2). */
struct SearchOptions
{
	double gaze_tilt_deg = -20;  ///< tilt while searching (negative: down)
	double pan_from_deg = -20, pan_to_deg = 20, pan_step_deg = 10;
	double head_move_time_s = 1.0;  ///< robot time per sweep position (move + grab)
	/** Optional: `reconstructed` (default): each view's stereo pair is reconstructed ([scene] of
	 * `[files] scene_file`); any other name is a simulated sensor the app must provide
	 * (`exact_sim`: the objects' exact wire-frames, corrupted; for tests). */
	SceneSource scene_source = SceneSource::Reconstructed;
	std::string scene_sensor = "reconstructed";  ///< the name as configured
	/** Optional, simulated scenes only: grab each view's stereo pair for the record anyway. */
	bool render_stereo = true;
	/** Optional, reconstructed only: the recogniser also verifies in the view's stereo images
	 * (recog::ImageVerifier, [image_verification] of recognition_file). */
	bool image_verification = true;
	/** Optional: the views cover the plan's table in front of the station (TableCoverage.h: the
	 * pans span its top, tilt and vergence follow it, pan_step_deg apart); false (default): the
	 * fixed pans pan_from_deg..pan_to_deg at gaze_tilt_deg (thesis 6.4). */
	bool cover_table = false;
	/** Optional: the first view that recognises ends the sweep (default, thesis 7.2.2); false:
	 * every view of the first pass is recognised and the most confident answer wins. */
	bool stop_at_first = true;
	/** Optional, with image verification: in a view where the target is not recognised, the
	 * other models of the database are recognised and the target is sought again behind those
	 * found (recog::searchBehindFound, as mrolr-recognize does); false (default): the target
	 * alone. */
	bool behind_found = false;
	/** Optional, with image verification: in a view where the target is recognised, the other
	 * models of the database are recognised too, and the target's answer is refused there when
	 * one of them is found at its place with a higher image score (recog::betterExplained); the
	 * sweep goes on. false (default): the target alone. */
	bool rival_models = false;
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
	/** Fixed in code: if the model's grasp line is infeasible, also the grasp turned about O's
	 * vertical axis in steps of this, smallest turn first: 90° lets a box be taken across either
	 * pair of faces (0: the model's line only). */
	double grasp_yaw_search_deg = 90;
	/** Optional: a verification grasp further than this from the first is refused (the first is
	 * kept and the report says why): a wrong re-recognition must not throw the arm about. */
	double max_grasp_correction_mm = 40;
	/** Optional, for tests: the first recognised pose is moved this far along C0's x (left)
	 * before the grasp is planned, so the verification has a known error to correct. */
	double inject_pose_error_mm = 0;
	/** Optional: after closing (and after the lift) the robot holds the object when its jaws
	 * stay at least this far apart (the gripper's encoder; closed on nothing they meet). */
	double min_held_width_mm = 5;
	void loadFromConfigFile(const mrpt::config::CConfigFileBase& cfg, const std::string& section);
	void dump(std::ostream& out) const;
};

/** The whole mission configuration (robot side). */
struct MissionOptions
{
	std::string config_path;       ///< the mission file itself
	std::string name = "mission";  ///< [mission] name: used in the output folder name
	std::string plan_file;         ///< [mission] plan (or --plan), resolved
	Plan plan;                     ///< as loaded from plan_file, overrides applied
	std::string target;            ///< [mission] target: a model of the model database
	std::string models_dir;        ///< [files] models_dir: the model database, <name>.wf files
	NavigationMode mode = NavigationMode::Slam;
	bool obstacle_mode = false;  ///< look for obstacles before each step (thesis 5.8.1.2)
	unsigned seed = 1;           ///< every random draw of the robot side follows it
	double home_tolerance_m = 0.10;  ///< the robot believes it is home this close (its estimate)

	base::LabmateOptions labmate;
	base::TrajectoryOptions trajectory;
	geometry::BiSightOptions bisight;
	slam::SlamOptions slam;
	recog::RecognitionOptions recognition = recog::RecognitionOptions::defaults();
	arm::RtxOptions rtx;
	arm::GraspFeasibilityOptions grasp;
	arm::ArmMount dock;     ///< nominal T_C0inA of the docked arm (section [arm_mount])
	arm::MarkerOptions marker;  ///< the hand's calibration marker ([arm_marker] of the arm file)
	DeviceOptions devices;  ///< [device.base|head|arm|camera]
	NavigationOptions navigation;
	SearchOptions search;
	RetrievalOptions retrieval;
	DockingOptions docking;  ///< [docking]: where to drive when the arm cannot reach
	DockCalibrationOptions dock_calibration;  ///< [dock_calibration]: T_C0inA measured, eq 6.7.2
	PlaceOptions place;  ///< [place]: the retrieved object put down on the deck
	ObstacleOptions obstacle;  ///< [obstacle], read only when obstacle_mode is set
	/** [image_verification] of [files] recognition_file, read for reconstructed scenes with
	 * search.image_verification. */
	recog::ImageVerificationOptions image_verification;
	/** [vision] of [files] vision_file, read for landmark_sensor = images. */
	vision::VisionOptions vision;
	/** [scene] of [files] scene_file, read for reconstructed scenes. */
	stereo::SceneOptions scene;

	/** Where the plan comes from and what is overridden in it (`--plan`, `--set plan.…`). */
	struct PlanChoice
	{
		std::string file;  ///< empty: [mission] plan
		std::vector<PlanOverride> overrides;
	};
	/** Reads @p path and every file it names; throws util::ConfigError (file, section, key) or
	 * util::IniError (the plan's file, line, section, key). */
	static MissionOptions load(const std::string& path, const PlanChoice& plan = {});
	/** As load(), from an already open configuration (for tests that override keys); relative
	 * file names are resolved against @p base_dir. */
	static MissionOptions fromConfig(const mrpt::config::CConfigFileBase& cfg,
	                                 const std::string& base_dir, const PlanChoice& plan = {});
	void dump(std::ostream& out) const;
};

}  // namespace mrolr::mission
