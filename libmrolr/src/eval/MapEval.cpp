// mrolr-map's plan against the world's truth.
#include <mrolr/eval/MapEval.h>
#include <mrolr/slam/Chi2.h>

#include <cmath>

namespace mrolr::eval
{
namespace
{
mission::NamedPose pose(const world::Waypoint& w)
{
	return {w.name, {w.z_m, w.x_m, w.phi_rad}};
}

const world::Patch* patchOf(const world::World& w, const std::string& name)
{
	for (const auto& p : w.patches)
		if (p.name == name) return &p;
	return nullptr;
}

Eigen::Vector3d truePoint(const mission::PlanFeature& k, const world::World& w,
                          const world::Landmark& l)
{
	const auto* patch = patchOf(w, k.id);
	if (!patch || !k.p_viewinW) return l.p_LinW;
	const Eigen::Vector3d o = *k.p_viewinW, d = (k.p_FinW - o).normalized();
	const double along = patch->normal.dot(d);
	if (std::abs(along) < 1e-9) return patch->centre_m;
	return o + d * (patch->normal.dot(patch->centre_m - o) / along);
}

nlohmann::json timeline(const mission::Timeline& t)
{
	nlohmann::json events = nlohmann::json::array();
	for (const auto& e : t.events())
		events.push_back({{"t_s", e.time_s}, {"stage", e.stage}, {"event", e.text}});
	return events;
}

std::vector<std::string> names(const std::vector<mission::NamedPose>& v)
{
	std::vector<std::string> out;
	for (const auto& p : v) out.push_back(p.name);
	return out;
}
}  // namespace

mission::Plan surveyPlanOf(const world::World& w)
{
	mission::Plan p;
	p.path = w.path;
	const auto& m = w.mission;
	if (!w.findWaypoint(m.table_waypoint) || !w.findWaypoint(m.home_waypoint))
		throw world::WorldError(w.path + " [mission]: table_waypoint '" + m.table_waypoint +
		                        "' and home_waypoint '" + m.home_waypoint +
		                        "' must be waypoints of [waypoints]");
	for (const auto& wp : w.waypoints) p.waypoints.push_back(pose(wp));
	for (const auto& wp : w.waypoints)
	{
		if (wp.name == m.table_waypoint) break;
		p.route.push_back(pose(wp));
	}
	if (p.route.empty())
		throw world::WorldError(w.path + " [mission] table_waypoint: the route before it is empty "
		                                 "(the first waypoint is the start pose)");
	p.stations.push_back(pose(*w.findWaypoint(m.table_waypoint)));
	p.home = pose(*w.findWaypoint(m.home_waypoint));
	for (const auto& t : w.tables)
		p.tables.push_back({t.name, t.x_m, t.z_m, t.yaw_deg, t.length_m, t.depth_m,
		                    t.top_height_m});
	if (w.has_room)
		p.room = mission::PlanRoom{w.room.min_m.x(), w.room.min_m.z(), w.room.max_m.x(),
		                           w.room.max_m.z()};
	return p;
}

std::vector<mission::SurveyTarget> surveyTargetsOf(const world::World& w)
{
	std::vector<mission::SurveyTarget> out;
	for (const auto& l : w.landmarks)
		if (l.known) out.push_back({l.name, l.p_LinW});
	return out;
}

std::vector<FeatureCheck> checkKnownFeatures(const mission::Plan& plan, const world::World& w)
{
	const double bound = slam::chi2Quantile(0.95, 3);
	std::vector<FeatureCheck> out;
	for (const auto& k : plan.known_features)
	{
		const auto* l = w.findLandmark(k.id);
		if (!l) continue;
		FeatureCheck c;
		c.id = k.id;
		c.p_true = truePoint(k, w, *l);
		c.error_m = k.p_FinW - c.p_true;
		c.mahalanobis_sq = c.error_m.cwiseQuotient(k.sigma_m.cwiseMax(1e-9)).squaredNorm();
		c.consistent = c.mahalanobis_sq <= bound;
		out.push_back(c);
	}
	return out;
}

nlohmann::json mapReportJson(const mission::MapBuildResult& r,
                             const std::vector<FeatureCheck>& checks)
{
	nlohmann::json features = nlohmann::json::array();
	for (const auto& k : r.plan.known_features)
		features.push_back({{"id", k.id},
		                    {"p_FinW", {k.p_FinW.x(), k.p_FinW.y(), k.p_FinW.z()}},
		                    {"sigma_m", {k.sigma_m.x(), k.sigma_m.y(), k.sigma_m.z()}}});
	nlohmann::json eval = nlohmann::json::array();
	int consistent = 0;
	for (const auto& c : checks)
	{
		eval.push_back({{"id", c.id},
		                {"error_m", {c.error_m.x(), c.error_m.y(), c.error_m.z()}},
		                {"error_norm_m", c.error_m.norm()},
		                {"mahalanobis_sq", c.mahalanobis_sq},
		                {"consistent_95", c.consistent}});
		consistent += c.consistent;
	}
	return {{"stopped", r.stopped},
	        {"failure", r.failure},
	        {"route", names(r.plan.route)},
	        {"stations", names(r.plan.stations)},
	        {"home", r.plan.home.name},
	        {"locked", r.locked},
	        {"not_locked", r.not_locked},
	        {"features_mapped", r.all.size()},
	        {"known_features_saved", r.plan.known_features.size()},
	        {"known_features", features},
	        {"eval", {{"checked", checks.size()}, {"consistent_95", consistent}, {"features", eval}}},
	        {"timeline", timeline(r.timeline)},
	        {"simulated_seconds", r.timeline.simulatedSeconds()},
	        {"compute_seconds", r.timeline.computeSeconds()}};
}

}  // namespace mrolr::eval
