#include <mrolr/apps/MissionApp.h>
#include <mrolr/apps/ReplayCheck.h>
#include <mrolr/apps/TruthRecording.h>
#include <mrolr/apps/MissionSummary.h>
#include <mrolr/apps/RunConfiguration.h>
#include <mrolr/apps/SerialEmulation.h>
#include <mrolr/apps/SimulatedWorld.h>
#include <mrolr/apps/StopSignals.h>
#include <mrolr/apps/TclapSupport.h>
#include <mrolr/eval/MissionOutputs.h>
#include <mrolr/eval/MissionTruth.h>
#include <mrolr/mission/DeviceRecorder.h>
#include <mrolr/mission/MissionDevices.h>
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
using nlohmann::json;
using summary::attachProgress;
using summary::printSummary;

/** report.json `recording`: the rawlog's size and the writer's time. */
json recordingJson(const io::ObservationQueue::Stats& s, const std::string& rawlog)
{
	return {{"rawlog", rawlog},
	        {"records", s.records},
	        {"rawlog_bytes", s.bytes},
	        {"images", s.images},
	        {"image_bytes", s.image_bytes},
	        {"writer_seconds", s.write_s},
	        {"robot_waited_seconds", s.wait_s},
	        {"max_queued", s.max_queued}};
}

void printRecording(std::ostream& out, const json& r)
{
	out << std::fixed << std::setprecision(1) << "  recording: " << r["records"] << " records ("
	    << r["rawlog_bytes"].get<double>() / 1e6 << " MB) and " << r["images"] << " images ("
	    << r["image_bytes"].get<double>() / 1e6 << " MB), written in "
	    << r["writer_seconds"].get<double>() << " s off the robot's path (it waited "
	    << std::setprecision(2) << r["robot_waited_seconds"].get<double>() << " s)\n";
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

bool isPlanOverride(const std::string& text)
{
	return text.rfind("plan.", 0) == 0;
}

/** "plan.KEY=V" → ([plan], KEY, V); "plan.SECTION.KEY=V" → (SECTION, KEY, V). */
mission::PlanOverride planOverride(const std::string& text)
{
	const std::string rest = text.substr(5);
	if (rest.find('.') == std::string::npos || rest.find('.') > rest.find('='))
	{
		const auto eq = rest.find('=');
		if (eq == std::string::npos || eq == 0)
			throw util::UsageError("--set '" + text + "': expected plan.[SECTION.]KEY=VALUE");
		return {"plan", rest.substr(0, eq), rest.substr(eq + 1)};
	}
	return splitOverride(rest);
}
}  // namespace

void MissionApp::initialize(const std::vector<std::string>& args)
{
	command = args;
	TCLAP::CmdLine cmd(
	    "mrolr-mission: navigate, search, recognise, retrieve and return home (docs/mission.md)",
	    ' ', "1");
	TCLAP::ValueArg<std::string> cfg("", "config", "mission .ini (default config/mission_sim.ini)",
	                                 false, config_path, "FILE", cmd);
	TCLAP::ValueArg<std::string> plan("", "plan", "the robot's plan (default [mission] plan)",
	                                  false, "", "FILE", cmd);
	TCLAP::ValueArg<std::string> world(
	    "", "world", "the simulated world (default [simulator] world_file); read by the simulator only",
	    false, "", "FILE", cmd);
	TCLAP::ValueArg<std::string> out("", "out", "output folder (default out/<name>-<timestamp>)",
	                                 false, "", "DIR", cmd);
	TCLAP::SwitchArg js("", "json", "print report.json instead of the summary", cmd);
	TCLAP::SwitchArg q("", "quiet", "no progress line", cmd);
	TCLAP::MultiArg<std::string> set(
	    "", "set", "override a key of the mission file, or of the plan with plan.[SECTION.]KEY", false,
	    "SECTION.KEY=VALUE", cmd);
	TCLAP::ValueArg<std::string> replay(
	    "", "replay",
	    "run the robot side on this recording (mission.rawlog) instead of devices, with the run's "
	    "configuration (its run/mission.ini unless --config)",
	    false, "", "RAWLOG", cmd);
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
	replay_path = replay.getValue();
	config_path = replay_path.empty() || cfg.isSet() ? util::projectFile(cfg.getValue()) : "";
	if (!replay_path.empty() && (world.isSet() || emu.getValue()))
		throw util::UsageError("--replay runs on the recording alone: it takes no --world and no "
		                       "--serial-emulation");
	plan_path = plan.getValue();
	world_path = world.getValue();
	out_dir = out.getValue();
	json = js.getValue();
	quiet = q.getValue();
	overrides = set.getValue();
	for (const auto& o : overrides) isPlanOverride(o) ? (void)planOverride(o) : (void)splitOverride(o);
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

namespace
{
/** The mission file in memory with the non-plan overrides written in. */
util::ConfigFile openWithOverrides(const std::string& path,
                                   const std::vector<std::string>& overrides)
{
	auto cfg = util::openConfigFile(path);
	for (const auto& o : overrides)
		if (!isPlanOverride(o))
		{
			const auto [section, key, value] = splitOverride(o);
			cfg.set(section, key, value, path + " with --set");
		}
	return cfg;
}
}  // namespace

mission::MissionOptions MissionApp::loadOptions() const
{
	const auto cfg = openWithOverrides(config_path, overrides);
	mission::MissionOptions::PlanChoice plan{plan_path, {}};
	for (const auto& o : overrides)
		if (isPlanOverride(o)) plan.overrides.push_back(planOverride(o));
	auto loaded = mission::MissionOptions::fromConfig(
	    cfg, std::filesystem::path(config_path).parent_path().string(), plan);
	loaded.config_path = config_path;
	return loaded;
}

int MissionApp::run(std::ostream& out, std::ostream& progress)
{
	if (help_shown) return 0;
	if (!replay_path.empty()) return replay(out, progress);
	StopSignals signals;  // from the start: a stop before the mission moves is still a safe stop
	options = loadOptions();
	const auto cfg = openWithOverrides(config_path, overrides);
	const auto dir = std::filesystem::path(config_path).parent_path().string();
	std::unique_ptr<SimulatedWorld> world;
	if (SimulatedWorld::needed(options) || serial_emulation || !world_path.empty())
		world = std::make_unique<SimulatedWorld>(cfg, dir, options, world_path);
	std::unique_ptr<SerialEmulation> emulation;
	if (serial_emulation)
	{
		emulation = std::make_unique<SerialEmulation>(world->lab(), emulation_faults);
		emulation->useIn(options);
	}
	mission::MissionDevices devices(options.devices,
	                                world ? world->devices() : mission::SimDevices{});
	if (out_dir.empty()) out_dir = "out/" + options.name + "-" + utcStamp();
	RunInputs run_inputs{config_path, {}, world_path, command};
	for (const auto& o : overrides)
		if (!isPlanOverride(o)) run_inputs.sets.push_back(splitOverride(o));
	const std::string run_config = writeRunConfiguration(run_inputs, options, out_dir);
	const std::string rawlog = (std::filesystem::path(out_dir) / "mission.rawlog").string();
	mission::DeviceRecorder recorder(rawlog, devices.devices(),
	                                 geometry::BiSightHead(options.bisight));
	if (world)
	{  // the world side's truth, beside what the robot recorded (a replay never reads it)
		recorder.world_truth = truthRecorder(world->lab());
		recorder.write(recorder.world_truth());
	}
	mission::Mission m(options, recorder.devices(),
	                   world ? world->sensors() : mission::SimulatedSensors{});
	if (!quiet) attachProgress(m, progress);
	m.stop_flag = &recorder.stopFlag(&signals.flag());
	m.decisions = &recorder;
	result = m.run();
	stop_signal = signals.received();
	recorder.flush();  // the whole recording in the file before the outputs name it
	if (!quiet) progress << "\n";
	const auto truth = world ? std::optional(eval::truthOf(world->lab())) : std::nullopt;
	auto written = eval::writeMissionOutputs(result, options, truth ? &*truth : nullptr, out_dir);
	files = written.files, report = written.report;
	files.push_back(rawlog);
	if (truth)
	{
		files.push_back((std::filesystem::path(out_dir) / "truth.json").string());
		std::ofstream(files.back()) << eval::truthJson(*truth).dump(2) << "\n";
	}
	files.push_back(run_config);
	report["recording"] = recordingJson(recorder.stats(), rawlog);
	std::ofstream(written.files.front()) << report.dump(2) << "\n";  // report.json
	if (json)
		out << report.dump(2) << "\n";
	else
	{
		printSummary(out, report, out_dir);
		printRecording(out, report["recording"]);
	}
	if (stop_signal) return 128 + stop_signal;
	return report["success"].get<bool>() ? 0 : 3;
}

}  // namespace mrolr::apps
