// trajectory.png: the run seen from above (io/TopViewPlot.h), what the robot knew and, with the
// truth, what happened.
#include <mrolr/eval/MissionOutputs.h>
#include <mrolr/io/TopViewPlot.h>

#include <algorithm>
#include <cmath>

namespace mrolr::eval
{
namespace
{
using io::Marker;
using mission::PathSample;
using V2 = Eigen::Vector2d;
constexpr int kMaxPathEllipses = 30;  // a readable number of the estimate's ellipses

V2 zxOf(const Eigen::Vector3d& xv_zxphi)
{
	return xv_zxphi.head<2>();
}

std::vector<V2> pathOf(const std::vector<PathSample>& path, Eigen::Vector3d PathSample::*field)
{
	std::vector<V2> out;
	for (const auto& s : path) out.push_back(zxOf(s.*field));
	return out;
}

/** The estimate where the robot said it was lost: the sample at or after each "lost:" note. */
std::vector<V2> lostPlaces(const mission::MissionResult& r)
{
	std::vector<V2> out;
	for (const auto& e : r.timeline.events())
	{
		if (e.text.rfind("lost:", 0) != 0 || r.path.empty()) continue;
		const auto it = std::lower_bound(r.path.begin(), r.path.end(), e.time_s,
		                                 [](const PathSample& s, double t) { return s.time_s < t; });
		out.push_back(zxOf((it == r.path.end() ? r.path.back() : *it).estimate));
	}
	return out;
}

void addPlan(io::TopViewPlot& plot, const mission::MissionOptions& o)
{
	std::vector<std::vector<V2>> tables;
	for (const auto& t : o.plan.tables)
		tables.push_back(io::TopViewPlot::rectangle({t.z_m, t.x_m}, t.yaw_deg * M_PI / 180,
		                                            t.depth_m, t.length_m));
	plot.addPolygons("table (plan)", tables, {{170, 170, 170}, 1});
	if (o.plan.room)
		plot.includeExtent({o.plan.room->min_z_m, o.plan.room->min_x_m},
		                   {o.plan.room->max_z_m, o.plan.room->max_x_m});
	std::vector<V2> waypoints;
	for (const auto& w : o.plan.waypoints) waypoints.push_back(zxOf(w.xv_zxphi));
	plot.addPoints("waypoint (plan)", waypoints, Marker::Diamond, {{120, 120, 120}, 1}, 9);
}

void addTruth(io::TopViewPlot& plot, const MissionTruth& t)
{
	if (t.world)
	{
		if (t.world->has_room)
			plot.includeExtent({t.world->room.min_m.z(), t.world->room.min_m.x()},
			                   {t.world->room.max_m.z(), t.world->room.max_m.x()});
		std::vector<std::vector<V2>> obstacles;
		for (const auto& ob : t.world->obstacles)
			obstacles.push_back(io::TopViewPlot::rectangle(
			    {ob.z_m, ob.x_m}, ob.yaw_deg * M_PI / 180, ob.size_m.z(), ob.size_m.x()));
		plot.addPolygons("obstacle (true)", obstacles, {{60, 110, 160}, 1});
		std::vector<V2> landmarks;
		for (const auto& l : t.world->landmarks) landmarks.emplace_back(l.p_LinW.z(), l.p_LinW.x());
		plot.addPoints("landmark (true)", landmarks, Marker::Square, {{0, 0, 0}, 2}, 9);
	}
	std::vector<V2> path;
	for (const auto& s : t.steps) path.push_back(zxOf(s.xv_zxphi));
	plot.addPath("true path", path, {{0, 160, 0}, 2});
	std::vector<V2> objects;
	for (const auto& ob : t.objects)
		objects.emplace_back(ob.T_OinW.translation().z(), ob.T_OinW.translation().x());
	plot.addPoints("object (true)", objects, Marker::Disc, {{0, 140, 255}, 1}, 8);
	if (t.contact)
		plot.addPoints("contact (true): " + t.contact->what, {t.contact->p_zx}, Marker::TiltedCross,
		               {{0, 0, 0}, 3}, 24);
}

void addEstimate(io::TopViewPlot& plot, const mission::MissionResult& r)
{
	plot.addPath("dead reckoning", pathOf(r.path, &PathSample::odometry), {{0, 0, 220}, 2});
	plot.addPath("estimate", pathOf(r.path, &PathSample::estimate), {{200, 0, 0}, 2});
	std::vector<Eigen::Matrix2d> P;
	for (const auto& s : r.path) P.push_back(io::zxBlockOfVehicle(s.P_vv));
	plot.addEllipses95("estimate, 95 % ellipse", pathOf(r.path, &PathSample::estimate), P,
	                   {{200, 0, 0}, 2}, kMaxPathEllipses);
	std::vector<V2> map;
	std::vector<Eigen::Matrix2d> P_map;
	for (const auto& m : r.map)
		map.emplace_back(m.p_FinW.z(), m.p_FinW.x()), P_map.push_back(io::zxMarginalOfPoint(m.P));
	plot.addPoints("landmark (mapped)", map, Marker::Cross, {{200, 0, 200}, 2}, 12);
	plot.addEllipses95("landmark, 95 % ellipse", map, P_map, {{200, 0, 200}, 2});
	std::vector<V2> vias;
	for (const auto& e : r.obstacle.events)
		for (const auto& p : e.via_zx_inW) vias.push_back(p);
	plot.addPoints("detour waypoint", vias, Marker::Diamond, {{0, 120, 255}, 2}, 12);
	plot.addPoints("lost (the robot said)", lostPlaces(r), Marker::Star, {{0, 200, 255}, 2}, 18);
	if (r.collided)
		plot.addPoints("collision (estimate)", {zxOf(r.collision_estimate)}, Marker::TiltedCross,
		               {{0, 0, 255}, 3}, 24);
}
}  // namespace

void writeTrajectoryPng(const mission::MissionResult& r, const mission::MissionOptions& o,
                        const MissionTruth* truth, const std::string& path)
{
	io::TopViewPlot plot("mission '" + o.name + "', seed " + std::to_string(o.seed) + ": " +
	                     (r.success ? "succeeded" : "failed") +
	                     (truth ? "" : " (the robot's view, no truth)"));
	addPlan(plot, o);
	if (truth) addTruth(plot, *truth);
	addEstimate(plot, r);
	plot.write(path);
}

}  // namespace mrolr::eval
