#pragma once
/** The run's effective configuration kept with its outputs, `<out>/run/`: the mission file as it
 * ran (every `--set` written in), a copy of every file its `[files]` names and of the model
 * database, the plan as used (plan overrides applied, its patches beside it) and the command.
 * `mrolr-mission --config <out>/run/mission.ini` runs the same mission again: the same seed, the
 * same files. The world stays the simulator's and is named by its absolute path; nothing of it
 * is copied. */
#include <mrolr/mission/MissionOptions.h>

#include <array>
#include <string>
#include <vector>

namespace mrolr::apps
{
struct RunInputs
{
	std::string config_path;                       ///< the mission file given
	std::vector<std::array<std::string, 3>> sets;  ///< its --set SECTION.KEY=VALUE (not plan.*)
	std::string world_path;                        ///< --world, or empty ([simulator] world_file)
	std::vector<std::string> command;              ///< the command line as given
};

/** The time now in UTC as `YYYYmmdd-HHMMSS`, for the default output folders. */
std::string utcStamp();

/** Writes `<out_dir>/run/` for @p in and the loaded @p o; returns the path of its mission.ini.
 * Throws std::runtime_error naming the file that could not be read or written. */
std::string writeRunConfiguration(const RunInputs& in, const mission::MissionOptions& o,
                                  const std::string& out_dir);

}  // namespace mrolr::apps
