// mrolr-mission --replay: the robot side on the recording's devices, then the check against the
// run it replays (docs/mission.md "Recording and replay").
#include <mrolr/apps/MissionApp.h>
#include <mrolr/apps/ReplayCheck.h>
#include <mrolr/apps/TruthRecording.h>
#include <mrolr/apps/MissionSummary.h>
#include <mrolr/eval/MissionEval.h>
#include <mrolr/eval/MissionOutputs.h>
#include <mrolr/mission/DevicePlayback.h>
#include <mrolr/mission/MissionOutputs.h>
#include <mrolr/util/Cli.h>
#include <mrolr/util/Config.h>

#include <filesystem>
#include <fstream>
#include <iomanip>
#include <ostream>

namespace mrolr::apps
{
namespace fs = std::filesystem;
using Json = nlohmann::json;
using summary::attachProgress;
using summary::printSummary;

namespace
{
Json readJson(const fs::path& p)
{
	std::ifstream f(p);
	try
	{
		return Json::parse(f);
	}
	catch (const Json::exception& e)
	{
		throw util::ConfigError(p.string() + ": not valid JSON: " + e.what());
	}
}

void requireDevicesOnly(const mission::MissionOptions& o)
{
	if (o.navigation.landmark_source == mission::LandmarkSource::Simulated)
		throw util::ConfigError("[navigation] landmark_sensor = " + o.navigation.landmark_sensor +
		                        ": a simulator's sensor, not a device; a replay has only the "
		                        "recorded devices");
	if (o.search.scene_source == mission::SceneSource::Simulated)
		throw util::ConfigError("[search] scene_sensor = " + o.search.scene_sensor +
		                        ": a simulator's sensor, not a device; a replay has only the "
		                        "recorded devices");
}

/** The original run's truth (truth.json and the recording's GROUND_TRUTH), for eval only. */
std::optional<eval::MissionTruth> recordedTruth(const fs::path& dir, const std::string& rawlog)
{
	if (!fs::exists(dir / "truth.json")) return std::nullopt;
	auto t = eval::truthFromJson(readJson(dir / "truth.json"), (dir / "truth.json").string());
	t.steps = recordedTruthSteps(rawlog);
	return t;
}
}  // namespace

std::string MissionApp::replayConfig() const
{
	const fs::path run = fs::path(replay_path).parent_path() / "run" / "mission.ini";
	if (!fs::exists(run))
		throw util::ConfigError("the recording " + replay_path + " has no " + run.string() +
		                        " beside it: give the run's configuration with --config");
	return run.string();
}

int MissionApp::replay(std::ostream& out, std::ostream& progress)
{
	if (!fs::exists(replay_path))
		throw util::ConfigError("--replay " + replay_path + ": no such recording");
	const fs::path original = fs::path(replay_path).parent_path();
	if (config_path.empty()) config_path = replayConfig();
	options = loadOptions();
	requireDevicesOnly(options);
	mission::DevicePlayback playback(replay_path);
	if (out_dir.empty()) out_dir = (original / "replay").string();
	if (fs::weakly_canonical(out_dir) == fs::weakly_canonical(original))
		throw util::UsageError("--out " + out_dir + " is the recording's own folder: give another");
	mission::Mission m(options, playback.devices());
	if (!quiet) attachProgress(m, progress);
	m.stop_flag = &playback.stopFlag();
	result = m.run();
	if (!quiet) progress << "\n";
	auto written = eval::writeMissionOutputs(result, options, nullptr, out_dir);
	files = written.files, report = written.report;
	const auto truth = recordedTruth(original, replay_path);
	if (truth) eval::evaluateMission(report, *truth);
	const bool has_original = fs::exists(original / "report.json");
	const auto differences =
	    has_original ? reportDifferences(readJson(original / "report.json"), report) : std::vector<std::string>{};
	report["replay"] = {{"recording", replay_path},
	                    {"configuration", config_path},
	                    {"calls_recorded", playback.recorded()},
	                    {"calls_served", playback.served()},
	                    {"recording_torn", playback.torn().empty() ? Json(nullptr) : Json(playback.torn())},
	                    {"divergence", result.divergence.empty() ? Json(nullptr) : Json(result.divergence)},
	                    {"original_report", has_original},
	                    {"differences", differences}};
	std::ofstream(fs::path(out_dir) / "report.json") << report.dump(2) << "\n";
	std::ofstream(fs::path(out_dir) / "report.md") << mission::reportMarkdown(report);
	if (this->json)
		out << report.dump(2) << "\n";
	else
	{
		printSummary(out, report, out_dir);
		out << "  replay: " << playback.served() << " of " << playback.recorded()
		    << " recorded device calls answered; "
		    << (!result.divergence.empty() ? "DIVERGED: " + result.divergence
		        : !has_original           ? std::string("no original report to compare with")
		        : differences.empty()     ? std::string("the report matches the original's")
		                                  : std::to_string(differences.size()) +
		                                    " report fields differ from the original's, first " +
		                                    differences.front())
		    << "\n";
	}
	return result.divergence.empty() && differences.empty() ? 0 : 3;
}

}  // namespace mrolr::apps
