// report.json (the robot's part) and report.md of a mission.
#include <mrolr/arm/GripperPose.h>
#include <mrolr/mission/MissionOutputs.h>
#include <mrolr/slam/Chi2.h>
#include <mrolr/util/JsonOptional.h>

#include <cmath>
#include <iomanip>
#include <sstream>

namespace mrolr::mission
{
namespace
{
using nlohmann::json;

json vec(const Eigen::VectorXd& v)
{
	return std::vector<double>(v.data(), v.data() + v.size());
}

json mat3(const Eigen::Matrix3d& M)
{
	json rows = json::array();
	for (int i = 0; i < 3; ++i) rows.push_back({M(i, 0), M(i, 1), M(i, 2)});
	return rows;
}

json graspJson(const RetrievalResult& g)
{
	const auto p = arm::gripperFromPose(g.T_GinA);
	json j = {{"feasible", g.feasible},
	          {"reasons", g.reasons},
	          {"arm_moved", g.attempted},
	          {"T_OinA_mm", matrix34(g.T_OinA)},
	          {"T_GinA_mm", matrix34(g.T_GinA)},
	          {"T_GinO_mm", matrix34(g.T_GinO)},
	          {"grasp_turn_deg", g.grasp_turn_deg},
	          {"grasp_pose",
	           {{"p_mm", {p.p_mm.x(), p.p_mm.y(), p.p_mm.z()}},
	            {"yaw_deg", p.yaw_deg},
	            {"pitch_deg", p.pitch_deg},
	            {"roll_deg", p.roll_deg}}},
	          {"verified", g.verified},
	          {"correction_mm", g.correction_mm},
	          {"correction_deg", g.correction_deg},
	          {"correction_applied", g.correction_applied},
	          {"correction_refused", g.correction_refused},
	          {"T_OinC0_first_mm", matrix34(g.T_OinC0_first_mm)},
	          {"T_OinC0_verified_mm", matrix34(g.T_OinC0_verified_mm)},
	          {"width_closed_mm", g.width_closed_mm},
	          {"width_lifted_mm", g.width_lifted_mm},
	          {"held", g.retrieved},
	          {"object_error_before_mm", nullptr},
	          {"object_error_after_mm", nullptr},
	          {"grasp_error_mm", nullptr}};
	if (g.attempted)
	{
		const auto jj = g.joints.toMmDeg();
		j["joints_d1mm_qdeg"] = std::vector<double>(jj.begin(), jj.end());
	}
	return j;
}

json dockingJson(const DockingResult& d)
{
	json j = {{"needed", d.needed},
	          {"planned", d.planned},
	          {"reached", d.reached},
	          {"reasons_before", d.reasons_before},
	          {"reasons_nearest", d.reasons_nearest},
	          {"candidates", d.candidates},
	          {"candidates_checked", d.candidates_checked},
	          {"candidates_near_walls", d.candidates_near_walls},
	          {"reason", d.reason},
	          {"compute_seconds", d.compute_s},
	          {"recognised", d.recognised},
	          {"ambiguous", d.ambiguous},
	          {"swept_again", d.swept_again},
	          {"found_again", d.found_again},
	          {"docked_again", d.docked_again},
	          {"frame", d.frame ? json(*d.frame) : json(nullptr)},
	          {"pose_zxphi", nullptr}};
	if (d.planned)
	{
		const auto& xv = d.chosen.pose.xv_zxphi;
		j["pose_zxphi"] = {xv[0], xv[1], xv[2]};
		j["side"] = d.chosen.side;
		j["travel_m"] = d.chosen.travel_m;
		j["lateral_m"] = d.chosen.lateral_m;
	}
	return j;
}

json placeJson(const PlaceResult& p)
{
	json j = {{"planned", p.plan.found},
	          {"attempted", p.attempted},
	          {"placed", p.placed},
	          {"reason", p.reason},
	          {"candidates", p.plan.candidates},
	          {"with_ik_solution", p.plan.solved},
	          {"tested_arm_poses", p.plan.tested_poses},
	          {"compute_seconds", p.plan.compute_s},
	          {"arm_moves", p.plan.carry.size() + p.plan.leave.size()},
	          {"width_before_opening_mm", p.width_before_mm},
	          {"spot_in_C0_mm", nullptr}};
	if (p.plan.found)
	{
		const auto& s = p.plan.p_spotInC0_mm;
		j["spot_in_C0_mm"] = {s.x(), s.y(), s.z()};
		j["yaw_deg"] = p.plan.yaw_deg;
		j["drop_mm"] = p.plan.drop_mm;
	}
	return j;
}

json dockCalibrationJson(const DockCalibrationResult& c)
{
	return {{"attempted", c.attempted},
	        {"calibrated", c.calibrated},
	        {"reason", c.reason},
	        {"poses_planned", c.poses_planned},
	        {"sightings", c.sightings},
	        {"rms_mm", c.fit.points ? json(c.fit.rms_mm) : json(nullptr)},
	        {"max_residual_mm", c.fit.points ? json(c.fit.max_mm) : json(nullptr)},
	        {"change_from_nominal_mm", c.calibrated ? json(c.change_mm) : json(nullptr)},
	        {"change_from_nominal_deg", c.calibrated ? json(c.change_deg) : json(nullptr)},
	        {"T_C0inA_mm", matrix34(c.T_C0inA)},
	        {"frames", c.frames},
	        {"seconds", c.time_s},
	        {"compute_seconds", c.compute_s}};
}

json timelineJson(const Timeline& t)
{
	json events = json::array();
	for (const auto& e : t.events())
		events.push_back({{"t_s", e.time_s}, {"stage", e.stage}, {"event", e.text}});
	return events;
}

json linksJson(const std::vector<LinkReport>& links)
{
	json out = json::array();
	for (const auto& l : links)
		out.push_back({{"device", l.section}, {"port", l.port}, {"resends", l.resends}});
	return out;
}

json pathJson(const std::vector<PathSample>& path)
{
	json out = json::array();
	for (const auto& s : path)
		out.push_back({{"t_s", s.time_s},
		               {"device_t_s", s.device_time_s},
		               {"estimate", vec(s.estimate)},
		               {"P_vv", mat3(s.P_vv)},
		               {"odometry", vec(s.odometry)},
		               {"features", s.features},
		               {"bumper", s.bumper}});
	return out;
}

json mapJson(const std::vector<MappedLandmark>& map)
{
	json out = json::array();
	for (const auto& m : map)
		out.push_back(
		    {{"label", m.label}, {"p_FinW", vec(m.p_FinW)}, {"P", mat3(m.P)}, {"known", m.known}});
	return out;
}

/** Every update's NIS and the fraction inside the two-sided 95 % bounds of χ²₃. */
json nisJson(const std::vector<NisRecord>& nis)
{
	const double lo = slam::chi2Quantile(0.025, 3), hi = slam::chi2Quantile(0.975, 3);
	json values = json::array();
	int inside = 0;
	for (const auto& n : nis)
	{
		values.push_back({{"t_s", n.time_s}, {"feature", n.feature}, {"nis", n.nis},
		                  {"accepted", n.accepted}});
		inside += n.nis >= lo && n.nis <= hi;
	}
	return {{"count", nis.size()},
	        {"bounds_95", {lo, hi}},
	        {"fraction_inside_95", nis.empty() ? json(nullptr) : json(double(inside) / nis.size())},
	        {"values", values}};
}

/** The estimated table top in C0 as {"n": [3], "d_mm"} (n·p + d_mm is a point's height), or null. */
json tablePlaneJson(const SearchResult& s)
{
	if (!s.table_plane.found) return nullptr;
	const auto& n = s.table_plane_C0.n_S;
	return {{"n", {n.x(), n.y(), n.z()}}, {"d_mm", s.table_plane_C0.d_mm}};
}

/** Every pose of an ambiguous answer in C0 (mm) with its support; empty when not ambiguous. */
json posesJson(const SearchResult& s)
{
	json out = json::array();
	const Eigen::Isometry3d T_LinC0 = s.T_OinC0_mm * s.T_OinL_mm.inverse();
	for (const auto& p : s.recognition.poses)
		out.push_back({{"T_OinC0_mm", matrix34(T_LinC0 * p.T_OinS)}, {"support", p.support}});
	return out;
}

json tablePlaneSummary(const SearchResult& s)
{
	const auto& e = s.table_plane;
	return {{"found", e.found},
	        {"plane_C0", tablePlaneJson(s)},
	        {"horizontal_features", e.horizontal},
	        {"standing_features", e.standing},
	        {"support_mm", e.support_mm},
	        {"reason", e.found ? json(nullptr) : json(e.reason)},
	        {"error_mm", nullptr},
	        {"error_deg", nullptr}};
}

json robotJson(const MissionResult& r, const MissionOptions& o)
{
	const PathSample last = r.path.empty() ? PathSample{} : r.path.back();
	json j = {{"success", r.success},
	          {"home", {{"name", r.home.name}, {"zxphi", vec(r.home.xv_zxphi)}}},
	          {"home_estimate_error_m", r.home_estimate_error_m},
	          {"home_tolerance_m", o.home_tolerance_m},
	          {"final_estimate_zxphi", vec(last.estimate)},
	          {"final_estimate_P_vv", mat3(last.P_vv)},
	          {"final_odometry_zxphi", vec(last.odometry)},
	          {"held_width_mm", r.held_width_mm},
	          {"on_board", r.place.placed},
	          {"arm_docked_home", r.arm_docked_home},
	          {"collided", r.collided},
	          {"collision_estimate_zxphi", vec(r.collision_estimate)},
	          {"dock_T_C0inA_mm", matrix34(o.dock.T_C0inA)},
	          {"head_height_m", o.bisight.head_height_m},
	          {"path", pathJson(r.path)},
	          {"map", mapJson(r.map)}};
	if (r.found)
		j["recognition"] = {{"T_OinC0_mm", matrix34(r.search.T_OinC0_mm)},
		                    {"frame", r.search.frame ? json(*r.search.frame) : json(nullptr)},
		                    {"search_estimate_zxphi", vec(r.search_xv_estimate)},
		                    {"table_plane_C0", tablePlaneJson(r.search)}};
	return j;
}
}  // namespace

json matrix34(const Eigen::Isometry3d& T)
{
	json rows = json::array();
	for (int i = 0; i < 3; ++i) rows.push_back({T(i, 0), T(i, 1), T(i, 2), T(i, 3)});
	return rows;
}

Eigen::Isometry3d isometryFrom(const json& rows)
{
	if (!rows.is_array() || rows.size() != 3)
		throw std::invalid_argument("a transform must be 3 rows of [R | t]");
	Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
	for (int i = 0; i < 3; ++i)
	{
		if (!rows[i].is_array() || rows[i].size() != 4)
			throw std::invalid_argument("a transform row must have 4 numbers");
		for (int k = 0; k < 4; ++k) T.matrix()(i, k) = rows[i][k].get<double>();
	}
	return T;
}

json reportJson(const MissionResult& r, const MissionOptions& o)
{
	json j = {{"mission", o.name},
	          {"success", r.success},
	          {"failure", r.failure},
	          {"stopped", r.stopped},
	          {"interrupted", r.interrupted},
	          {"replay_divergence", r.divergence.empty() ? json(nullptr) : json(r.divergence)},
	          {"serial_links", linksJson(r.links)},
	          {"target", r.target},
	          {"plan", o.plan_file},
	          {"seed", o.seed},
	          {"found", r.found},
	          {"found_instance", nullptr},
	          {"found_at_station", r.found_at_station},
	          {"stations_searched", r.stations_searched},
	          {"retrieved", r.retrieved},
	          {"returned_home", r.returned_home},
	          {"mode", o.mode == NavigationMode::Slam ? "slam" : "dead_reckoning"},
	          {"final_position_error_m", nullptr},
	          {"final_heading_error_deg", nullptr},
	          {"final_estimate_error_m", nullptr},
	          {"dead_reckoning_error_m", nullptr},
	          {"object_rotation_error_deg", nullptr},
	          {"object_translation_error_mm", nullptr},
	          {"grasp_correction_mm", r.retrieval.verified ? json(r.retrieval.correction_mm)
	                                                       : json(nullptr)},
	          {"stages", r.timeline.stageSeconds()},
	          {"stage_compute_seconds", r.timeline.stageComputeSeconds()},
	          {"compute_seconds", r.timeline.computeSeconds()},
	          {"simulated_seconds", r.timeline.simulatedSeconds()},
	          {"render_seconds", r.timeline.renderSeconds()},
	          {"stereo_pairs", r.shots.size()},
	          {"obstacle_pairs", countShots(r.shots, StereoShot::Purpose::Obstacle)},
	          {"steps", r.path.size()},
	          {"measurements", r.measurements},
	          {"measurements_rejected", r.measurements_rejected},
	          {"measurements_lost", r.measurements_lost},
	          {"features_deleted", r.features_deleted},
	          {"navigation_source", r.navigation_source},
	          {"navigation_pairs", r.navigation_pairs},
	          {"image_searches", r.image_searches},
	          {"image_matches", r.image_matches},
	          {"jointly_rejected", r.jointly_rejected},
	          {"lost_events", r.lost_events},
	          {"recoveries", r.recoveries},
	          {"features", r.map.size()},
	          {"nis", nisJson(r.nis)},
	          {"robot", robotJson(r, o)},
	          {"eval", nullptr},
	          {"timeline", timelineJson(r.timeline)}};
	if (o.obstacle_mode) j["obstacle"] = obstacleJson(r.obstacle);
	if (r.found)
		j["recognition"] = {{"confidence", r.search.recognition.confidence},
		                    {"score", r.search.recognition.score},
		                    {"level", r.search.recognition.level},
		                    {"views", r.search.views},
		                    {"T_OinC0_mm", matrix34(r.search.T_OinC0_mm)},
		                    {"T_OinC0_true_mm", nullptr},
		                    {"table_plane", tablePlaneSummary(r.search)},
		                    {"ambiguous", r.search.recognition.ambiguous},
		                    {"found_behind", r.search.recognition.occluders},
		                    {"poses", posesJson(r.search)}};
	if (r.found) j["retrieval"] = graspJson(r.retrieval);
	if (r.found) j["retrieval"]["docking"] = dockingJson(r.docking);
	if (r.found) j["retrieval"]["dock_calibration"] = dockCalibrationJson(r.dock_calibration);
	if (r.found) j["retrieval"]["place"] = placeJson(r.place);
	if (r.found)
		j["retrieval"]["ambiguity"] = {
		    {"ambiguous", r.retrieval.ambiguity.poses > 1},
		    {"poses", r.retrieval.ambiguity.poses},
		    {"poses_gripped_alike", r.retrieval.ambiguity.poses_fitted},
		    {"resolution", AmbiguityHandling::name(r.retrieval.ambiguity.resolution)}};
	if (r.found)
		j["retrieval"]["frame"] = r.retrieval.frame ? json(*r.retrieval.frame) : json(nullptr);
	if (r.found) j["T_OinA"] = matrix34(r.retrieval.T_OinA);
	return j;
}

}  // namespace mrolr::mission
