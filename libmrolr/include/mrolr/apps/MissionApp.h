#pragma once
/** `mrolr-mission`: runs the fetch mission of a mission file (issue 9, docs/mission.md):
 *
 *     mrolr-mission [--config config/mission_sim.ini] [--out DIR] [--json] [--quiet]
 *                   [--set SECTION.KEY=VALUE]... [--serial-emulation [--emulate-delay-ms N]
 *                   [--emulate-drop-probability P]]
 *
 * `--set` overrides a key of the mission file (e.g. `--set device.base.port=/dev/pts/4`);
 * `--serial-emulation` serves the simulated lab's devices on pseudo-terminals and drives them
 * through the serial drivers (every device `driver = serial`), with optional reply delays and
 * byte loss.
 *
 * Writes report.json, report.md, trajectory.png, mission.3Dscene and mission.rawlog into DIR
 * (default out/<name>-<UTC timestamp>), prints a progress line while running and a summary (or the
 * report as JSON) at the end. Exit code 0 when the mission succeeded, 3 when it ran but failed
 * (not found, unreachable, not home; the outputs are written), 1 for an error such as a malformed
 * configuration (nothing moves), 2 for bad arguments. */
#include <mrolr/hw_serial/DeviceEmulator.h>
#include <mrolr/mission/Mission.h>

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

	std::string config_path = "config/mission_sim.ini";
	std::string out_dir;  ///< empty: out/<name>-<timestamp>
	bool json = false, quiet = false, help_shown = false;
	std::vector<std::string> overrides;  ///< "section.key=value"
	bool serial_emulation = false;
	hw::FaultOptions emulation_faults;  ///< reply_delay_ms, drop_byte_probability
	mission::MissionOptions options;
	mission::MissionResult result;
	std::vector<std::string> files;  ///< outputs written
};

}  // namespace mrolr::apps
