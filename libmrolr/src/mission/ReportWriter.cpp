// report.json and report.md of a mission.
#include <mrolr/arm/GripperPose.h>
#include <mrolr/mission/MissionOutputs.h>

#include <cmath>
#include <iomanip>
#include <sstream>

namespace mrolr::mission
{
namespace
{
using nlohmann::json;

json matrix34(const Eigen::Isometry3d& T)
{
	json rows = json::array();
	for (int i = 0; i < 3; ++i) rows.push_back({T(i, 0), T(i, 1), T(i, 2), T(i, 3)});
	return rows;
}

json orNull(bool available, double v)
{
	return available ? json(v) : json(nullptr);
}

json finiteOrNull(double v)
{
	return orNull(std::isfinite(v), v);
}

json graspJson(const RetrievalResult& g)
{
	const auto p = arm::gripperFromPose(g.T_GinA);
	json j = {{"feasible", g.feasible},
	          {"reasons", g.reasons},
	          {"arm_moved", g.attempted},
	          {"T_OinA_mm", matrix34(g.T_OinA)},
	          {"T_GinA_mm", matrix34(g.T_GinA)},
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
	          {"object_error_before_mm", finiteOrNull(g.object_error_before_mm)},
	          {"object_error_after_mm", finiteOrNull(g.object_error_after_mm)},
	          {"grasp_error_mm", finiteOrNull(g.grasp_error_mm)},
	          {"grasped", g.grasped}};
	if (g.attempted)
	{
		const auto jj = g.joints.toMmDeg();
		j["joints_d1mm_qdeg"] = std::vector<double>(jj.begin(), jj.end());
	}
	return j;
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
		out.push_back({{"device", l.section},
		               {"port", l.port},
		               {"resends", l.resends},
		               {"emulated_lab_device", l.lab_behind_port}});
	return out;
}
}  // namespace

json reportJson(const MissionResult& r, const MissionOptions& o)
{
	const bool f = r.found && !r.search.instance.empty();
	json j = {{"mission", o.name},
	          {"success", r.success},
	          {"failure", r.failure},
	          {"stopped", r.stopped},
	          {"serial_links", linksJson(r.links)},
	          {"target", r.target},
	          {"found", r.found},
	          {"found_instance", r.found_instance},
	          {"found_at_station", r.found_at_station},
	          {"stations_searched", r.stations_searched},
	          {"retrieved", r.retrieved},
	          {"returned_home", r.returned_home},
	          {"mode", o.mode == NavigationMode::Slam ? "slam" : "dead_reckoning"},
	          {"final_position_error_m", r.final_position_error_m},
	          {"final_heading_error_deg", r.final_heading_error_deg},
	          {"final_estimate_error_m", r.final_estimate_error_m},
	          {"dead_reckoning_error_m", r.dead_reckoning_error_m},
	          {"object_rotation_error_deg", orNull(f, r.search.rotation_error_deg)},
	          {"object_translation_error_mm", orNull(f, r.search.translation_error_mm)},
	          {"grasp_correction_mm", orNull(r.retrieval.verified, r.retrieval.correction_mm)},
	          {"stages", r.timeline.stageSeconds()},
	          {"stage_compute_seconds", r.timeline.stageComputeSeconds()},
	          {"compute_seconds", r.timeline.computeSeconds()},
	          {"simulated_seconds", r.timeline.simulatedSeconds()},
	          {"render_seconds", r.timeline.renderSeconds()},
	          {"stereo_pairs", r.shots.size()},
	          {"steps", r.path.size()},
	          {"measurements", r.measurements},
	          {"measurements_rejected", r.measurements_rejected},
	          {"measurements_lost", r.measurements_lost},
	          {"features_deleted", r.features_deleted},
	          {"measurement_source", o.navigation.measurement_source},
	          {"navigation_pairs", r.navigation_pairs},
	          {"image_searches", r.image_searches},
	          {"image_matches", r.image_matches},
	          {"features", r.map.size()},
	          {"timeline", timelineJson(r.timeline)}};
	if (o.obstacle_mode) j["obstacle"] = obstacleJson(r.obstacle);
	if (r.found)
		j["recognition"] = {{"confidence", r.search.recognition.confidence},
		                    {"score", r.search.recognition.score},
		                    {"level", r.search.recognition.level},
		                    {"views", r.search.views},
		                    {"T_OinC0_mm", matrix34(r.search.T_OinC0)},
		                    {"T_OinC0_true_mm", matrix34(r.search.T_OinC0_true)}};
	if (r.found) j["retrieval"] = graspJson(r.retrieval);
	if (r.found) j["T_OinA"] = matrix34(r.retrieval.T_OinA);
	return j;
}

std::string reportMarkdown(const MissionResult& r, const MissionOptions& o)
{
	std::ostringstream s;
	s << std::fixed << std::setprecision(3);
	s << "# Mission " << o.name << ": " << (r.success ? "SUCCESS" : "FAILED") << "\n\n";
	if (!r.failure.empty()) s << "Reason: " << r.failure << "\n\n";
	s << "| item | value |\n|---|---|\n"
	  << "| target | " << r.target << " |\n| found | " << (r.found ? "yes" : "no")
	  << (r.found ? " (" + r.found_instance + " at " + r.found_at_station + ")" : "") << " |\n"
	  << "| stations searched | " << r.stations_searched << " |\n"
	  << "| retrieved | " << (r.retrieved ? "yes" : "no") << " |\n"
	  << "| returned home | " << (r.returned_home ? "yes" : "no") << " |\n"
	  << "| final position error (m) | " << r.final_position_error_m << " |\n"
	  << "| estimate error at home (m) | " << r.final_estimate_error_m << " |\n"
	  << "| dead-reckoning error at home (m) | " << r.dead_reckoning_error_m << " |\n";
	if (r.found)
		s << "| object pose error | " << r.search.translation_error_mm << " mm, "
		  << r.search.rotation_error_deg << " deg |\n| recognition confidence | "
		  << r.search.recognition.confidence << " (level " << r.search.recognition.level
		  << ") |\n| grasp correction (mm) | " << r.retrieval.correction_mm << " ("
		  << r.retrieval.correction_deg << " deg, "
		  << (r.retrieval.correction_applied   ? "applied"
		      : r.retrieval.correction_refused ? "refused"
		                                       : "not applied")
		  << ") |\n";
	s << "| simulated time (s) | " << r.timeline.simulatedSeconds() << " |\n"
	  << "| robot compute (s) | " << r.timeline.computeSeconds() << " |\n"
	  << "| simulator rendering (s) | " << r.timeline.renderSeconds() << " |\n";
	if (o.obstacle_mode)
		s << "| obstacle mode | " << r.obstacle.checks << " checks, " << r.obstacle.events.size()
		  << " obstacles avoided, " << r.obstacle.failed_looks << " failed looks |\n";
	for (const auto& l : r.links)
		s << "| serial " << l.section << " | " << l.port << ", " << l.resends << " resends |\n";
	s << "\n## Stages\n\n"
	  << "| stage | simulated s | compute s |\n|---|---|---|\n";
	for (const auto& [name, sec] : r.timeline.stageSeconds())
	{
		const auto& c = r.timeline.stageComputeSeconds();
		s << "| " << name << " | " << sec << " | " << (c.count(name) ? c.at(name) : 0.0) << " |\n";
	}
	s << "\n## Timeline\n\n";
	for (const auto& e : r.timeline.events())
		s << "- " << std::setprecision(1) << e.time_s << " s [" << e.stage << "] " << e.text
		  << "\n";
	if (r.found && !r.retrieval.reasons.empty())
	{
		s << "\n## Grasp problems\n\n";
		for (const auto& why : r.retrieval.reasons) s << "- " << why << "\n";
	}
	return s.str();
}

}  // namespace mrolr::mission
