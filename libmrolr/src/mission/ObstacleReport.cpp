// report.json's account of obstacle mode.
#include <mrolr/mission/ObstacleAvoidance.h>

#include <nlohmann/json.hpp>

namespace mrolr::mission
{
namespace
{
nlohmann::json eventJson(const ObstacleEvent& e)
{
	nlohmann::json via = nlohmann::json::array();
	for (const auto& v : e.via_zx_inW) via.push_back({v.x(), v.y()});
	const auto& s = e.sighting;
	return {{"time_s", e.time_s},
	        {"estimate_zxphi", {e.xv_estimate.x(), e.xv_estimate.y(), e.xv_estimate.z()}},
	        {"points", s.points},
	        {"near_m", s.near_m},
	        {"far_m", s.far_m},
	        {"left_m", s.left_m},
	        {"right_m", s.right_m},
	        {"side", e.detour.side > 0 ? "left" : "right"},
	        {"both_sides_blocked", e.detour.both_blocked},
	        {"points_left", e.detour.points_left},
	        {"points_right", e.detour.points_right},
	        {"waypoints_zx_inW", via}};
}
}  // namespace

nlohmann::json obstacleJson(const ObstacleReport& r)
{
	nlohmann::json events = nlohmann::json::array();
	for (const auto& e : r.events) events.push_back(eventJson(e));
	return {{"looks", r.looks},
	        {"checks", r.checks},
	        {"failed_looks", r.failed_looks},
	        {"obstacles", r.events.size()},
	        {"events", events}};
}

}  // namespace mrolr::mission
