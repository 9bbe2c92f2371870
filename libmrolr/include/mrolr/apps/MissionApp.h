#pragma once
/** `mrolr-mission`: runs the fetch mission of a mission file (docs/mission.md):
 *
 *     mrolr-mission [--config config/mission_sim.ini] [--plan P.ini] [--world W.ini] [--out DIR]
 *                   [--json] [--quiet] [--set SECTION.KEY=VALUE]... [--set plan.[SECTION.]KEY=V]
 *                   [--serial-emulation [--emulate-delay-ms N] [--emulate-drop-probability P]]
 *     mrolr-mission --replay out/X/mission.rawlog [--config C.ini] [--set ...] [--out DIR]
 *
 * The robot side reads the mission file, its calibration, its model database and its plan. When
 * a device is `driver = sim` (or a simulated sensor is named) the app also builds the simulated
 * lab of `--world` (default `[simulator] world_file`) — only the app reads the world — and after
 * the run eval checks the robot's report against the lab's truth. `--serial-emulation` serves the
 * lab's devices on pseudo-terminals and drives them through the serial drivers.
 *
 * Writes report.json, report.md, trajectory.png, mission.3Dscene, mission.rawlog (every device
 * call as it happens, mission/DeviceRecorder.h), truth.json (in-process runs: the world's truth
 * at the end, for eval only) and run/ into DIR (default out/<name>-<UTC timestamp>), prints a progress line while running and a summary (or the
 * report as JSON) at the end. SIGINT or SIGTERM stop the base and the arm safely and every output
 * is still written. Exit code 0 when the mission succeeded, 3 when it ran but failed, 130 / 143
 * when SIGINT / SIGTERM stopped it, 1 for an error such as a malformed configuration (nothing
 * moves), 2 for bad arguments.
 *
 * `--replay` runs the robot side again on a recording (mission/DevicePlayback.h) with the run's
 * own configuration (`<recording's folder>/run/mission.ini`, or --config), without a simulator,
 * and writes its outputs into DIR (default `<recording's folder>/replay`); eval rechecks it with
 * the recording's truth.json. Exit 0 when the replay reproduced the recorded run's report, 3 when
 * it diverged (report.json `replay.divergence` names the call, device and request) or its report
 * differs (`replay.differences`). */
#include <mrolr/hw_serial/DeviceEmulator.h>
#include <mrolr/mission/Mission.h>

#include <nlohmann/json.hpp>

#include <iosfwd>
#include <string>
#include <vector>

namespace mrolr::apps
{
class MissionApp
{
 public:
	/** Parses the command line (argv[0] first); throws util::UsageError for bad arguments. */
	void initialize(const std::vector<std::string>& args);
	/** Loads the configuration (util::ConfigError before anything moves), runs, writes outputs. */
	int run(std::ostream& out, std::ostream& progress);
	/** The mission file with the --set overrides applied (the file itself is not changed). */
	mission::MissionOptions loadOptions() const;
	/** --replay: the run's configuration kept beside the recording (util::ConfigError if none). */
	std::string replayConfig() const;

	std::string config_path = "config/mission_sim.ini";
	std::string plan_path;   ///< --plan (empty: [mission] plan)
	std::string world_path;  ///< --world (empty: [simulator] world_file)
	std::string out_dir;     ///< empty: out/<name>-<timestamp>
	std::string replay_path;  ///< --replay: the recording (mission.rawlog) to run on
	bool json = false, quiet = false, help_shown = false;
	std::vector<std::string> overrides;  ///< "section.key=value" ("plan." ones go to the plan)
	bool serial_emulation = false;
	hw_serial::FaultOptions emulation_faults;  ///< reply_delay_ms, drop_byte_probability
	mission::MissionOptions options;
	mission::MissionResult result;
	nlohmann::json report;           ///< report.json as written
	std::vector<std::string> files;  ///< outputs written
	std::vector<std::string> command;  ///< the arguments as given (kept in <out>/run/command.txt)
	int stop_signal = 0;             ///< SIGINT / SIGTERM that stopped the run, 0 if none

 private:
	int replay(std::ostream& out, std::ostream& progress);
};

}  // namespace mrolr::apps
