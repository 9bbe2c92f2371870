// mrolr-mission's summary and progress lines.
#include <mrolr/apps/MissionSummary.h>

#include <iomanip>
#include <iostream>
#include <sstream>

#include <unistd.h>

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
namespace
{
/** A terminal shows a line rewritten in place; a file or a pipe gets plain lines. */
bool isTerminal(const std::ostream& s)
{
	if (&s == &std::cerr) return isatty(STDERR_FILENO) == 1;
	if (&s == &std::cout) return isatty(STDOUT_FILENO) == 1;
	return false;
}

void progressFields(std::ostream& out, const std::string& stage, const mission::PathSample& s)
{
	out << "[mission] " << std::setw(12) << std::left << stage << " t=" << std::fixed
	    << std::setprecision(0) << std::setw(5) << s.time_s << " s  z=" << std::setprecision(2)
	    << s.estimate.x() << " x=" << s.estimate.y() << " features=" << s.features;
}

/** Mission time between two plain progress lines (besides one at each new stage). */
constexpr double kPlainLineEvery_s = 60.0;
}  // namespace

void attachProgress(mission::Mission& m, std::ostream& progress)
{
	if (isTerminal(progress))
	{
		m.on_progress = [&progress](const std::string& stage, const mission::PathSample& s)
		{
			progress << "\r";
			progressFields(progress, stage, s);
			progress << "   " << std::flush;
		};
		return;
	}
	m.on_progress = [&progress, last_stage = std::string(), last_s = -1e300](
	                    const std::string& stage, const mission::PathSample& s) mutable
	{
		if (stage == last_stage && s.time_s - last_s < kPlainLineEvery_s) return;
		last_stage = stage, last_s = s.time_s;
		progressFields(progress, stage, s);
		progress << "\n" << std::flush;
	};
}

}  // namespace mrolr::apps::summary
