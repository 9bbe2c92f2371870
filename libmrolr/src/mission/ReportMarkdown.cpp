// report.md: report.json for people.
#include <mrolr/mission/MissionOutputs.h>

#include <iomanip>
#include <sstream>

namespace mrolr::mission
{
namespace
{
using nlohmann::json;

std::string text(const json& v)
{
	if (v.is_null()) return "–";
	if (v.is_boolean()) return v.get<bool>() ? "yes" : "no";
	if (v.is_number_float())
	{
		std::ostringstream s;
		s << std::fixed << std::setprecision(3) << v.get<double>();
		return s.str();
	}
	if (v.is_string()) return v.get<std::string>();
	return v.dump();
}

const json& at(const json& j, const char* key)
{
	static const json null;
	return j.is_object() && j.contains(key) ? j.at(key) : null;
}

void row(std::ostringstream& s, const std::string& item, const json& v)
{
	s << "| " << item << " | " << text(v) << " |\n";
}

void summaryTable(std::ostringstream& s, const json& r)
{
	const json& robot = at(r, "robot");
	const json& eval = at(r, "eval");
	s << "| item | value |\n|---|---|\n";
	row(s, "target", at(r, "target"));
	row(s, "found (at station)", json(text(at(r, "found")) + " (" + text(at(r, "found_at_station")) + ")"));
	row(s, "stations searched", at(r, "stations_searched"));
	row(s, "robot: holds the object (jaw width, mm)", json(text(at(r, "retrieved")) + " (" + text(at(robot, "held_width_mm")) + ")"));
	row(s, "robot: home by its estimate (error m)", json(text(at(r, "returned_home")) + " (" + text(at(robot, "home_estimate_error_m")) + ")"));
	row(s, "navigation source", at(r, "navigation_source"));
	row(s, "NIS inside 95 % bounds", at(at(r, "nis"), "fraction_inside_95"));
	row(s, "eval: confirms the robot", at(eval, "confirms"));
	row(s, "eval: final position error (m)", at(r, "final_position_error_m"));
	row(s, "eval: estimate error at home (m)", at(r, "final_estimate_error_m"));
	row(s, "eval: dead-reckoning error at home (m)", at(r, "dead_reckoning_error_m"));
	row(s, "eval: object in the gripper", at(eval, "object_held"));
	row(s, "eval: object on the deck", at(eval, "object_on_board"));
	row(s, "eval: object pose error (mm)", at(r, "object_translation_error_mm"));
	row(s, "eval: object pose error (deg)", at(r, "object_rotation_error_deg"));
	row(s, "eval: collision", at(eval, "collision"));
	row(s, "grasp correction (mm)", at(r, "grasp_correction_mm"));
	row(s, "simulated time (s)", at(r, "simulated_seconds"));
	row(s, "robot compute (s)", at(r, "compute_seconds"));
	row(s, "simulator rendering (s)", at(r, "render_seconds"));
	for (const auto& l : at(r, "serial_links"))
		row(s, "serial " + text(at(l, "device")), json(text(at(l, "port")) + ", " + text(at(l, "resends")) + " resends"));
}
}  // namespace

std::string reportMarkdown(const json& r)
{
	std::ostringstream s;
	s << "# Mission " << text(at(r, "mission")) << ": "
	  << (at(r, "success").is_boolean() && at(r, "success").get<bool>() ? "SUCCESS" : "FAILED")
	  << "\n\n";
	if (!text(at(r, "failure")).empty() && !at(r, "failure").is_null())
		s << "Reason: " << text(at(r, "failure")) << "\n\n";
	summaryTable(s, r);
	s << "\n## Stages\n\n| stage | simulated s | compute s |\n|---|---|---|\n";
	for (const auto& [name, sec] : at(r, "stages").items())
		s << "| " << name << " | " << text(sec) << " | "
		  << text(at(at(r, "stage_compute_seconds"), name.c_str())) << " |\n";
	s << "\n## Timeline\n\n";
	for (const auto& e : at(r, "timeline"))
		s << "- " << std::fixed << std::setprecision(1) << at(e, "t_s").get<double>() << " s ["
		  << text(at(e, "stage")) << "] " << text(at(e, "event")) << "\n";
	const json& reasons = at(at(r, "retrieval"), "reasons");
	if (reasons.is_array() && !reasons.empty())
	{
		s << "\n## Grasp problems\n\n";
		for (const auto& why : reasons) s << "- " << text(why) << "\n";
	}
	return s.str();
}

}  // namespace mrolr::mission
