#include <mrolr/apps/MissionApp.h>
#include <mrolr/apps/TclapSupport.h>
#include <mrolr/mission/MissionOutputs.h>
#include <mrolr/mission/SerialEmulation.h>
#include <mrolr/util/Config.h>

#include <mrpt/config/CConfigFile.h>

#include <array>
#include <ctime>
#include <filesystem>
#include <fstream>
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
	for (const auto& l : r.links)
		out << "  serial " << l.section << " on " << l.port << ": " << l.resends << " resends\n";
	out << "  simulated " << std::setprecision(1) << r.timeline.simulatedSeconds()
	    << " s, robot compute " << std::setprecision(3) << r.timeline.computeSeconds()
	    << " s\n  outputs in " << dir << "\n";
}
/** "section.key=value" → (section, key, value); the key is after the last '.' before '='. */
std::array<std::string, 3> splitOverride(const std::string& text)
{
	const auto eq = text.find('=');
	const auto dot = eq == std::string::npos ? std::string::npos : text.rfind('.', eq);
	if (dot == std::string::npos || dot == 0 || dot + 1 == eq)
		throw util::UsageError("--set '" + text + "': expected SECTION.KEY=VALUE");
	return {text.substr(0, dot), text.substr(dot + 1, eq - dot - 1), text.substr(eq + 1)};
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
	TCLAP::MultiArg<std::string> set("", "set", "override a key of the mission file", false,
	                                 "SECTION.KEY=VALUE", cmd);
	TCLAP::SwitchArg emu("", "serial-emulation",
	                     "serve the simulated devices on pseudo-terminals and drive them through "
	                     "the serial drivers",
	                     cmd);
	TCLAP::ValueArg<int> delay("", "emulate-delay-ms", "emulated devices reply this late", false, 0,
	                           "N", cmd);
	TCLAP::ValueArg<double> drop("", "emulate-drop-probability",
	                             "emulated devices lose each reply byte with this chance", false, 0,
	                             "P", cmd);
	if (!parseTclap(cmd, args))
	{
		help_shown = true;
		return;
	}
	config_path = cfg.getValue();
	out_dir = out.getValue();
	json = js.getValue();
	quiet = q.getValue();
	overrides = set.getValue();
	for (const auto& o : overrides) splitOverride(o);
	serial_emulation = emu.getValue();
	emulation_faults.reply_delay_ms = delay.getValue();
	emulation_faults.drop_byte_probability = drop.getValue();
	if (delay.getValue() < 0 || delay.getValue() > 10000)
		throw util::UsageError("--emulate-delay-ms must be within [0, 10000]");
	if (!(drop.getValue() >= 0 && drop.getValue() <= 0.5))
		throw util::UsageError("--emulate-drop-probability must be within [0, 0.5]");
	if (!serial_emulation && (delay.isSet() || drop.isSet()))
		throw util::UsageError("--emulate-* options need --serial-emulation");
}

mission::MissionOptions MissionApp::loadOptions() const
{
	if (overrides.empty()) return mission::MissionOptions::load(config_path);
	if (!std::ifstream(config_path).good())
		throw util::ConfigError("cannot open mission configuration '" + config_path + "'");
	mrpt::config::CConfigFile cfg(config_path);
	for (const auto& o : overrides)
	{
		const auto [section, key, value] = splitOverride(o);
		cfg.write(section, key, value);
	}
	cfg.discardSavingChanges();  // never write the overrides back into the file
	auto loaded = mission::MissionOptions::fromConfig(
	    cfg, std::filesystem::path(config_path).parent_path().string());
	loaded.config_path = config_path;
	return loaded;
}

int MissionApp::run(std::ostream& out, std::ostream& progress)
{
	if (help_shown) return 0;
	options = loadOptions();
	std::shared_ptr<mission::SimulatedLab> lab;
	std::unique_ptr<mission::SerialEmulation> emulation;
	if (serial_emulation)
	{
		lab = std::make_shared<mission::SimulatedLab>(options);
		emulation = std::make_unique<mission::SerialEmulation>(*lab, emulation_faults);
		emulation->useIn(options);
	}
	if (out_dir.empty()) out_dir = "out/" + options.name + "-" + utcStamp();
	mission::Mission m(options, lab);
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
