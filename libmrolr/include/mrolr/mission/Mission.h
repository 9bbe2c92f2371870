#pragma once
/** The fetch mission (thesis 5.8, fig 5.8.1.5, 7.2): load the target model → drive the route →
 * at each search station sweep the head and recognise → dock, check and grasp with visual
 * verification → drive home; home empty-handed when the target is found nowhere. Runs on the
 * devices of its factory (MissionDevices: simulated or serial); perception is simulated from the
 * SimulatedLab's truth; docs/mission.md lists what is simulated and how. */
#include <mrolr/mission/MissionDevices.h>
#include <mrolr/mission/MissionOptions.h>
#include <mrolr/mission/Navigator.h>
#include <mrolr/mission/ObjectSearch.h>
#include <mrolr/mission/ObstacleAvoidance.h>
#include <mrolr/mission/Retrieval.h>
#include <mrolr/mission/Timeline.h>

#include <functional>
#include <memory>

namespace mrolr::mission
{
/** A stereo pair grabbed during a sweep, with the robot's state at that moment. */
struct StereoShot
{
	PathSample state;
	geometry::HeadAngles angles;
	mrpt::img::CImage left, right;
};

/** Everything the reports need. Poses (z, x, φ) in W; mm for object and arm poses. */
struct MissionResult
{
	bool success = false, found = false, retrieved = false, returned_home = false;
	std::string failure;  ///< reason when not successful
	/** A device failed (stopped answering, garbage, disconnect: failure names the device section
	 * and its port) or refused a command (a joint limit): the mission stopped where it was, the
	 * base commanded to stand still and the arm not moved again. */
	bool stopped = false;
	std::vector<LinkReport> links;  ///< serial devices: port and resends
	std::string target, found_instance, found_at_station;
	int stations_searched = 0;
	double final_position_error_m = 0, final_heading_error_deg = 0;
	double final_estimate_error_m = 0;  ///< |estimate − truth| at home
	double dead_reckoning_error_m = 0;  ///< |odometry − truth| at home
	SearchResult search;
	Eigen::Vector3d search_xv_true = Eigen::Vector3d::Zero();  ///< true pose at the last search
	RetrievalResult retrieval;
	Eigen::Vector3d home = Eigen::Vector3d::Zero();
	std::vector<PathSample> path;
	std::vector<StereoShot> shots;  ///< stereo pairs of the sweeps and obstacle looks
	ObstacleReport obstacle;        ///< obstacle mode: looks, obstacles seen, waypoints inserted
	std::vector<MappedLandmark> map;
	int measurements = 0, measurements_rejected = 0;
	int measurements_lost = 0, features_deleted = 0;  ///< lost_feature_probability, rule 5.7
	/** measurement_source = images: searches for a mapped feature, how many matched in both
	 * images, and the stereo pairs navigation grabbed (not in shots). */
	int image_searches = 0, image_matches = 0, navigation_pairs = 0;
	Timeline timeline;
	WorldObjects final_objects;
};

class Mission
{
 public:
	/** Builds the devices of o.devices now (serial ports opened and checked; util::ConfigError
	 * names the port key otherwise) around @p lab (default: a new SimulatedLab(o)); pass the lab
	 * that a SerialEmulation serves so that the mission's truth is the one behind the ports. */
	explicit Mission(const MissionOptions& o, std::shared_ptr<SimulatedLab> lab = nullptr);
	~Mission();
	/** Runs the whole mission; never throws for a mission-level failure (not found, unreachable):
	 * those are reported in the result. */
	MissionResult run();
	/** Progress callback: stage and the latest path sample. */
	std::function<void(const std::string& stage, const PathSample&)> on_progress;

 private:
	struct Impl;
	std::unique_ptr<Impl> impl_;
};

}  // namespace mrolr::mission
