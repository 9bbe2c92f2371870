#pragma once
/** The fetch mission (thesis 5.8, fig 5.8.1.5, 7.2): load the target model → drive the route →
 * at each search station sweep the head and recognise → dock, check and grasp with visual
 * verification → drive home; home empty-handed when the target is found nowhere. Runs on the
 * simulated devices (area sim); docs/mission.md lists what is simulated and how. */
#include <mrolr/mission/MissionOptions.h>
#include <mrolr/mission/Navigator.h>
#include <mrolr/mission/ObjectSearch.h>
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
	std::vector<StereoShot> shots;  ///< stereo pairs of the sweeps (render_stereo)
	std::vector<MappedLandmark> map;
	int measurements = 0, measurements_rejected = 0;
	Timeline timeline;
	WorldObjects final_objects;
};

class Mission
{
 public:
	explicit Mission(const MissionOptions& o);
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
