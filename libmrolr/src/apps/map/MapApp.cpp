#include <mrolr/apps/MapApp.h>
#include <mrolr/apps/SimulatedWorld.h>
#include <mrolr/apps/StopSignals.h>
#include <mrolr/apps/TclapSupport.h>
#include <mrolr/eval/MapEval.h>
#include <mrolr/mission/MissionDevices.h>
#include <mrolr/util/Config.h>

#include <mrpt/config/CConfigFile.h>

#include <filesystem>
#include <fstream>
#include <iomanip>
#include <ostream>

namespace mrolr::apps
{
namespace
{
namespace fs = std::filesystem;

/** The mission file with the overrides written in (never saved). */
util::ConfigFile configWith(const std::string& path, const std::vector<std::string>& sets)
{
	auto cfg = util::openConfigFile(path);
	for (const auto& s : sets)
	{
		const auto eq = s.find('='), dot = s.rfind('.', eq);
		if (eq == std::string::npos || dot == std::string::npos || dot == 0)
			throw util::UsageError("--set '" + s + "': expected SECTION.KEY=VALUE");
		cfg.set(s.substr(0, dot), s.substr(dot + 1, eq - dot - 1), s.substr(eq + 1),
		        path + " with --set");
	}
	return cfg;
}

void printSummary(std::ostream& out, const nlohmann::json& r, const std::string& plan)
{
	out << "plan written to " << plan
	    << (r["stopped"].get<bool>()
	            ? " (the drive stopped: " + r["failure"].get<std::string>() + ")"
	            : "")
	    << "\n  known features saved " << r["known_features_saved"] << " of "
	    << r["features_mapped"] << " mapped; locked on at the start: " << r["locked"].dump()
	    << "\n  eval: " << r["eval"]["consistent_95"] << " of " << r["eval"]["checked"]
	    << " named features within their 95 % bound\n";
	for (const auto& f : r["eval"]["features"])
		out << "    " << std::setw(16) << std::left << f["id"].get<std::string>() << " error "
		    << std::fixed << std::setprecision(3) << f["error_norm_m"].get<double>() << " m, d2 "
		    << std::setprecision(2) << f["mahalanobis_sq"].get<double>() << "\n";
}
}  // namespace

void MapApp::initialize(const std::vector<std::string>& args)
{
	TCLAP::CmdLine cmd("mrolr-map: a plan of a world from one drive (known features, thesis 5.6.2)",
	                   ' ', "1");
	TCLAP::ValueArg<std::string> world("", "world", "the world to map", true, "", "W.ini", cmd);
	TCLAP::ValueArg<std::string> out("", "out", "the plan to write (DIR/plan.ini)", true, "",
	                                 "FILE", cmd);
	TCLAP::ValueArg<std::string> cfg("", "config", "the robot's mission file", false, config_path,
	                                 "FILE", cmd);
	TCLAP::MultiArg<std::string> set("", "set", "override a key of the mission file", false,
	                                 "SECTION.KEY=VALUE", cmd);
	TCLAP::SwitchArg js("", "json", "print map_report.json", cmd);
	TCLAP::SwitchArg q("", "quiet", "no progress line", cmd);
	TCLAP::SwitchArg look("", "look-ahead",
	                      "look ahead for obstacles on the drive (the mission file's obstacle "
	                      "mode; off by default: the survey drive keeps its head on the features)",
	                      cmd);
	if (!parseTclap(cmd, args))
	{
		help_shown = true;
		return;
	}
	world_path = world.getValue(), out_path = out.getValue();
	config_path = util::projectFile(cfg.getValue());
	overrides = set.getValue(), json = js.getValue(), quiet = q.getValue();
	look_ahead = look.getValue();
}

int MapApp::run(std::ostream& out, std::ostream& progress)
{
	if (help_shown) return 0;
	const auto cfg = configWith(config_path, overrides);
	const auto dir = fs::path(config_path).parent_path().string();
	const auto w = world::World::load(world_path);
	// The plan a user writes for the place (no known features yet), read back as any plan is.
	fs::create_directories(fs::absolute(out_path).parent_path());
	eval::surveyPlanOf(w).save(out_path);
	auto o = mission::MissionOptions::fromConfig(cfg, dir, {out_path, {}});
	o.obstacle_mode = look_ahead;
	SimulatedWorld sim(cfg, dir, o, world_path);
	mission::MissionDevices devices(o.devices, sim.devices());
	mission::MapBuilder builder(o, devices.devices());
	StopSignals signals;
	builder.stop_flag = &signals.flag();
	if (!quiet)
		builder.on_progress = [&](const std::string& stage, const mission::PathSample& s)
		{
			progress << "\r[map] " << std::setw(7) << std::left << stage << " t=" << std::fixed
			         << std::setprecision(0) << std::setw(5) << s.time_s
			         << " s  features=" << s.features << "   " << std::flush;
		};
	result = builder.build(eval::surveyTargetsOf(w));
	if (!quiet) progress << "\n";
	result.plan.save(out_path);
	report = eval::mapReportJson(result, eval::checkKnownFeatures(result.plan, w));
	std::ofstream((fs::path(out_path).parent_path() / "map_report.json").string())
	    << report.dump(2) << "\n";
	if (json)
		out << report.dump(2) << "\n";
	else
		printSummary(out, report, out_path);
	if (signals.received()) return 128 + signals.received();
	return result.stopped ? 3 : 0;
}

}  // namespace mrolr::apps
