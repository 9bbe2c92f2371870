#pragma once
/** `mrolr-map`: makes a plan for a world as the thesis made its known features (5.6.2):
 *
 *     mrolr-map --world W.ini --out DIR/plan.ini [--config config/mission_sim.ini]
 *               [--set SECTION.KEY=VALUE]... [--look-ahead] [--json] [--quiet]
 *
 * --look-ahead drives with obstacle mode (a world with an obstacle on its route, such as
 * maps/lab_obstacle); without it the drive's head stays on the features it maps.
 * The route, station, home and tables are copied from the world as a user would write them
 * (eval::surveyPlanOf); the simulated robot, starting at the start pose (which defines W), points
 * its head at the world's `known` landmarks, locks on, drives the route once with SLAM from images
 * and saves the features it mapped well (mission::MapBuilder). No landmark position of the world
 * enters the plan. DIR gets plan.ini, one PNG per feature under patches/ and map_report.json, in
 * which eval compares the saved positions with the truth. Exit 0 when the plan was written, 3 when the drive stopped
 * (the plan is still written), 1 for an error, 2 for bad arguments. */
#include <mrolr/mission/MapBuilder.h>

#include <nlohmann/json.hpp>

#include <iosfwd>
#include <string>
#include <vector>

namespace mrolr::apps
{
class MapApp
{
 public:
	void initialize(const std::vector<std::string>& args);
	int run(std::ostream& out, std::ostream& progress);

	std::string world_path, out_path, config_path = "config/mission_sim.ini";
	std::vector<std::string> overrides;
	bool json = false, quiet = false, help_shown = false;
	bool look_ahead = false;  ///< --look-ahead: obstacle mode on the drive
	mission::MapBuildResult result;
	nlohmann::json report;  ///< map_report.json
};

}  // namespace mrolr::apps
