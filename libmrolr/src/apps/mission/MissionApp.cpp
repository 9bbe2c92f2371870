#include <mrolr/apps/MissionApp.h>
#include <mrolr/apps/TclapSupport.h>
#include <mrolr/mission/MissionOutputs.h>

#include <ctime>
#include <iomanip>
#include <ostream>
#include <sstream>

namespace mrolr::apps
{
namespace
{
std::string utcStamp()
{
	const std::time_t now = std::time(nullptr);
	std::tm tm{};
	gmtime_r(&now, &tm);
	std::ostringstream s;
	s << std::put_time(&tm, "%Y%m%d-%H%M%S");
	return s.str();
}

void printSummary(std::ostream& out, const mission::MissionResult& r, const std::string& dir)
{
	out << std::fixed << std::setprecision(3) << "mission " << (r.success ? "SUCCEEDED" : "FAILED")
	    << (r.failure.empty() ? "" : ": " + r.failure) << "\n  target " << r.target
	    << (r.found ? " found (" + r.found_instance + " at " + r.found_at_station + ")"
	                : " not found")
	    << ", retrieved " << (r.retrieved ? "yes" : "no") << ", home "
	    << (r.returned_home ? "yes" : "no") << " (error " << r.final_position_error_m << " m)\n";
	if (r.found)
		out << "  object pose error " << r.search.translation_error_mm << " mm, "
		    << r.search.rotation_error_deg << " deg; grasp correction " << r.retrieval.correction_mm
		    << " mm\n";
	out << "  simulated " << std::setprecision(1) << r.timeline.simulatedSeconds()
	    << " s, robot compute " << std::setprecision(3) << r.timeline.computeSeconds()
	    << " s\n  outputs in " << dir << "\n";
}
}  // namespace

void MissionApp::initialize(const std::vector<std::string>& args)
{
	TCLAP::CmdLine cmd(
	    "mrolr-mission: navigate, map, search, recognise, retrieve and return home "
	    "(docs/mission.md)",
	    ' ', "1");
	TCLAP::ValueArg<std::string> cfg("", "config", "mission .ini (default config/mission_sim.ini)",
	                                 false, config_path, "FILE", cmd);
	TCLAP::ValueArg<std::string> out("", "out", "output folder (default out/<name>-<timestamp>)",
	                                 false, "", "DIR", cmd);
	TCLAP::SwitchArg js("", "json", "print report.json instead of the summary", cmd);
	TCLAP::SwitchArg q("", "quiet", "no progress line", cmd);
	if (!parseTclap(cmd, args))
	{
		help_shown = true;
		return;
	}
	config_path = cfg.getValue();
	out_dir = out.getValue();
	json = js.getValue();
	quiet = q.getValue();
}

int MissionApp::run(std::ostream& out, std::ostream& progress)
{
	if (help_shown) return 0;
	options = mission::MissionOptions::load(config_path);
	if (out_dir.empty()) out_dir = "out/" + options.name + "-" + utcStamp();
	mission::Mission m(options);
	if (!quiet)
		m.on_progress = [&progress](const std::string& stage, const mission::PathSample& s)
		{
			progress << "\r[mission] " << std::setw(12) << std::left << stage << " t=" << std::fixed
			         << std::setprecision(0) << std::setw(5) << s.time_s
			         << " s  z=" << std::setprecision(2) << s.estimate.x()
			         << " x=" << s.estimate.y() << " features=" << s.features << "   "
			         << std::flush;
		};
	result = m.run();
	if (!quiet) progress << "\n";
	files = mission::writeOutputs(result, options, out_dir);
	if (json)
		out << mission::reportJson(result, options).dump(2) << "\n";
	else
		printSummary(out, result, out_dir);
	return result.success ? 0 : 3;
}

}  // namespace mrolr::apps
