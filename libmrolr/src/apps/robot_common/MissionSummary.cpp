// mrolr-mission's summary and progress lines.
#include <mrolr/apps/MissionSummary.h>

#include <iomanip>
#include <sstream>

namespace mrolr::apps::summary
{
std::string num(const json& v, int precision)
{
	if (!v.is_number()) return "n/a";
	std::ostringstream s;
	s << std::fixed << std::setprecision(precision) << v.get<double>();
	return s.str();
}

void printSummary(std::ostream& out, const json& r, const std::string& dir)
{
	const json& e = r["eval"];
	out << "mission " << (r["success"].get<bool>() ? "SUCCEEDED" : "FAILED")
	    << (r["failure"].get<std::string>().empty() ? "" : ": " + r["failure"].get<std::string>())
	    << "\n  robot: target " << r["target"].get<std::string>()
	    << (r["found"].get<bool>() ? " found at " + r["found_at_station"].get<std::string>()
	                               : " not found")
	    << ", has it " << (!r["retrieved"].get<bool>() ? "no"
	                       : r["robot"].value("on_board", false) ? "yes (on its deck)"
	                                                               : "yes (in its gripper)")
	    << ", home "
	    << (r["returned_home"].get<bool>() ? "yes" : "no") << " (its estimate "
	    << num(r["robot"]["home_estimate_error_m"]) << " m from home)\n";
	if (!e.is_null())
		out << "  eval: home error " << num(r["final_position_error_m"]) << " m, object "
		    << (e["object_on_board"].get<bool>() ? "on the deck"
		        : e["object_held"].get<bool>() ? "in the gripper"
		                                       : "not retrieved")
		    << ", object pose error "
		    << num(r["object_translation_error_mm"]) << " mm, "
		    << num(r["object_rotation_error_deg"]) << " deg\n";
	out << "  navigation from " << r["navigation_source"].get<std::string>() << ": "
	    << r["navigation_pairs"] << " stereo pairs, NIS inside 95 % bounds "
	    << num(r["nis"]["fraction_inside_95"], 2) << "\n";
	for (const auto& l : r["serial_links"])
		out << "  serial " << l["device"].get<std::string>() << " on "
		    << l["port"].get<std::string>() << ": " << l["resends"] << " resends\n";
	out << "  simulated " << num(r["simulated_seconds"], 1) << " s, robot compute "
	    << num(r["compute_seconds"]) << " s\n  outputs in " << dir << "\n";
}


/** The progress line on @p progress while @p m runs. */
void attachProgress(mission::Mission& m, std::ostream& progress)
{
	m.on_progress = [&progress](const std::string& stage, const mission::PathSample& s)
	{
		progress << "\r[mission] " << std::setw(12) << std::left << stage << " t=" << std::fixed
		         << std::setprecision(0) << std::setw(5) << s.time_s
		         << " s  z=" << std::setprecision(2) << s.estimate.x() << " x=" << s.estimate.y()
		         << " features=" << s.features << "   " << std::flush;
	};
}
}  // namespace mrolr::apps::summary
