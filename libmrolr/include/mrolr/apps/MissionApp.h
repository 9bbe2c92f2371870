#pragma once
/** `mrolr-mission`: runs the fetch mission of a mission file (issue 9, docs/mission.md):
 *
 *     mrolr-mission [--config config/mission_sim.ini] [--out DIR] [--json] [--quiet]
 *
 * Writes report.json, report.md, trajectory.png, mission.3Dscene and mission.rawlog into DIR
 * (default out/<name>-<UTC timestamp>), prints a progress line while running and a summary (or the
 * report as JSON) at the end. Exit code 0 when the mission succeeded, 3 when it ran but failed
 * (not found, unreachable, not home; the outputs are written), 1 for an error such as a malformed
 * configuration (nothing moves), 2 for bad arguments. */
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

	std::string config_path = "config/mission_sim.ini";
	std::string out_dir;  ///< empty: out/<name>-<timestamp>
	bool json = false, quiet = false, help_shown = false;
	mission::MissionOptions options;
	mission::MissionResult result;
	std::vector<std::string> files;  ///< outputs written
};

}  // namespace mrolr::apps
