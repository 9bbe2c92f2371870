// Obstacle mode joined to a navigator: its look-ahead decides before each translation.
#include <mrolr/mission/MissionOptions.h>
#include <mrolr/mission/Navigator.h>
#include <mrolr/mission/ObstacleAvoidance.h>

namespace mrolr::mission
{
void attachObstacleAvoidance(Navigator& nav, ObstacleAvoidance& avoidance, const MissionOptions& o)
{
	avoidance.setKnownTables(o.plan.tables, o.obstacle.table_margin_m);
	nav.max_detours_per_leg = o.obstacle.max_detours_per_leg;
	nav.before_translation = [&avoidance](const Eigen::Vector3d& e, const Eigen::Vector3d& goal)
	{ return avoidance.check(e, goal); };
}

}  // namespace mrolr::mission
