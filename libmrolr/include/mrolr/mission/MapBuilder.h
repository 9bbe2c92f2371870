#pragma once
/** A plan made as the thesis made its known features (5.6.2, paper §4): from the start pose, which
 * defines W, the head is pointed at each landmark an operator names and the feature there is
 * locked on and triangulated; then the robot drives the route, the stations and home once with
 * SLAM from images, measuring those features again from other places and mapping features of its
 * own. The features it mapped well (small covariance, matched often) are saved with their patches
 * and viewpoints as the plan's known features: the positions are the robot's own estimates, never
 * a survey. The route, stations, home and tables are given (the user's plan of the place). */
#include <mrolr/mission/Mission.h>

#include <string>
#include <vector>

namespace mrolr::mission
{
/** Where an operator points the head for a named known feature (W, m). */
struct SurveyTarget
{
	std::string id;
	Eigen::Vector3d p_aim_inW = Eigen::Vector3d::Zero();
};

struct MapBuildResult
{
	Plan plan;                             ///< the given plan with the saved known features
	std::vector<std::string> locked;       ///< targets locked on at the start
	std::vector<std::string> not_locked;   ///< targets that could not be (with why)
	std::vector<SavedFeature> all;         ///< every feature mapped at the end
	std::vector<PathSample> path;
	std::vector<NisRecord> nis;
	Timeline timeline;
	bool stopped = false;
	std::string failure;
};

class MapBuilder
{
 public:
	/** @p o.plan: route, stations, home and tables (its known features are not used). */
	MapBuilder(const MissionOptions& o, RobotDevices devices);
	/** The survey and the drive; never throws for a device failure or the bumper (reported). */
	MapBuildResult build(const std::vector<SurveyTarget>& targets);
	std::atomic<bool>* stop_flag = nullptr;
	std::function<void(const std::string& stage, const PathSample&)> on_progress;

	/** A feature is saved when its largest standard deviation is at most this (m) ... */
	static constexpr double kMaxSavedSigma_m = 0.05;
	/** ... and it was matched at least this often (its first measurement not counted). */
	static constexpr int kMinSavedMatches = 3;

 private:
	MissionOptions o_;
	RobotDevices dev_;
};

}  // namespace mrolr::mission
