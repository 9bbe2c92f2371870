#pragma once
/** The fetch mission (thesis 5.8, fig 5.8.1.5, 7.2), the robot side: load the target model from
 * the model database → drive the plan's route → at each search station sweep the head and
 * recognise → dock, check and grasp with visual verification → drive home; home empty-handed when
 * the target is found nowhere. It sees the world only through its devices (hw:: interfaces: the
 * simulator's, serial drivers or ROS topics) and reads only the robot's own files (calibration,
 * models, plan). It decides success from what it believes: home by its own estimate, the object
 * held by its gripper's jaw width (until it puts it down on its deck). eval checks that belief against the truth after the run. */
#include <mrolr/hw/SimulatedSensors.h>
#include <mrolr/mission/DeckPlacement.h>
#include <mrolr/mission/MissionOptions.h>
#include <mrolr/mission/Navigator.h>
#include <mrolr/mission/ObjectSearch.h>
#include <mrolr/mission/ObstacleAvoidance.h>
#include <mrolr/mission/Retrieval.h>
#include <mrolr/mission/Timeline.h>

#include <atomic>
#include <functional>
#include <memory>

namespace mrolr::mission
{
class DecisionLog;

/** A serial link's counters, for the report. */
struct LinkReport
{
	std::string section, port;
	int resends = 0;  ///< requests that had to be sent again (lost, late or damaged replies)
};

/** The devices the mission drives. All three must be set. */
struct RobotDevices
{
	hw::BaseDevice* base = nullptr;
	hw::HeadDevice* head = nullptr;
	hw::ArmDevice* arm = nullptr;
	std::function<std::vector<LinkReport>()> links;  ///< serial links' counters (optional)
};

/** The simulator's shortcut sensors, set only when the configuration names them (tests). */
struct SimulatedSensors
{
	hw::LandmarkSensor* landmarks = nullptr;  ///< `[navigation] landmark_sensor`
	hw::SceneSensor* scenes = nullptr;        ///< `[search] scene_sensor`
};

/** A stereo pair grabbed during a sweep, with the robot's state at that moment. */
struct StereoShot
{
	/** Why the pair was taken: a view of the table (sweep or verification) or a look ahead for
	 * obstacles. */
	enum class Purpose
	{
		Table,
		Obstacle,
		Calibration  ///< the arm presenting its marker (DockCalibration.h)
	};
	PathSample state;
	geometry::HeadAngles angles;
	mrpt::img::CImage left, right;
	uint64_t frame = 0;
	Purpose purpose = Purpose::Table;
};

/** How many of @p shots were taken for @p purpose. */
size_t countShots(const std::vector<StereoShot>& shots, StereoShot::Purpose purpose);

/** Everything the robot knows after a run. Poses (z, x, φ) in W; mm for object and arm poses. */
struct MissionResult
{
	/** The robot's claim: found, held (jaw width) and home (its estimate), not stopped. */
	bool success = false, found = false, retrieved = false, returned_home = false;
	std::string failure;  ///< reason when not successful
	/** A device failed (stopped answering, garbage, disconnect: failure names the device section
	 * and its port) or refused a command (a joint limit), the bumper was pressed, or a stop was
	 * requested: the mission stopped where it was, the base commanded to stand still and the arm
	 * not moved again. */
	bool stopped = false;
	bool interrupted = false;  ///< stopped by SIGINT or SIGTERM
	bool collided = false;     ///< stopped by the bumper
	/** A replay (DevicePlayback) stopped at its first divergence: the call, device and request
	 * the recording does not hold. Empty otherwise. */
	std::string divergence;
	Eigen::Vector3d collision_estimate = Eigen::Vector3d::Zero();  ///< where it believed it was
	std::vector<LinkReport> links;  ///< serial devices: port and resends
	std::string target, found_at_station;
	int stations_searched = 0;
	NamedPose home;
	double home_estimate_error_m = 0;  ///< |estimate − home| at the end: the robot's own belief
	double held_width_mm = 0;          ///< jaw distance at the end (0 when nothing was grasped)
	SearchResult search;
	Eigen::Vector3d search_xv_estimate = Eigen::Vector3d::Zero();  ///< estimate at the search
	RetrievalResult retrieval;
	DockingResult docking;  ///< the drive to where the arm reaches, if one was needed
	DockCalibrationResult dock_calibration;  ///< T_C0inA measured before the grasp
	PlaceResult place;  ///< the object put down on the deck after the lift
	/** The arm's platform (thesis 7.0): docked after the object was found, de-coupled before the
	 * drive home unless it still holds the object (then it rides home docked). */
	bool arm_docked = false, arm_docked_home = false;
	std::string arm_undock_refused;  ///< why de-coupling failed, if it did
	std::vector<PathSample> path;
	std::vector<StereoShot> shots;  ///< stereo pairs of the sweeps and obstacle looks
	ObstacleReport obstacle;        ///< obstacle mode: looks, obstacles seen, waypoints inserted
	std::vector<MappedLandmark> map;
	std::vector<NisRecord> nis;  ///< every filter update's NIS
	int measurements = 0, measurements_rejected = 0;
	int measurements_lost = 0, features_deleted = 0;  ///< lost_feature_probability, rule 5.7
	/** `images` or the simulated sensor's name; the stereo pairs navigation grabbed (not in
	 * shots), the searches for a mapped feature and how many matched in both images. */
	std::string navigation_source;
	int image_searches = 0, image_matches = 0, navigation_pairs = 0;
	int jointly_rejected = 0;             ///< matches left out by the joint compatibility test
	int lost_events = 0, recoveries = 0;  ///< times it knew it was lost / found the map again
	Timeline timeline;
};

class Mission
{
 public:
	/** Checks that the devices are set and that every simulated sensor the configuration names
	 * is given (util::ConfigError naming the key otherwise), before anything moves. */
	Mission(const MissionOptions& o, RobotDevices devices, SimulatedSensors sensors = {});
	~Mission();
	/** Runs the whole mission; never throws for a mission-level failure (not found, unreachable,
	 * a device failure, the bumper, a stop request): those are reported in the result. */
	MissionResult run();
	/** Progress callback: stage and the latest path sample. */
	std::function<void(const std::string& stage, const PathSample&)> on_progress;
	/** Set (from a signal handler) to stop the mission safely before its next motion. */
	std::atomic<bool>* stop_flag = nullptr;
	/** Where the decisions go as they are made (a recording, DeviceRecorder); may be null. */
	DecisionLog* decisions = nullptr;

 private:
	struct Impl;
	std::unique_ptr<Impl> impl_;
};

}  // namespace mrolr::mission
