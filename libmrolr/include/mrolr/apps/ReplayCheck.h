#pragma once
/** How `mrolr-mission --replay` checks a replay against the run it replays. */
#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace mrolr::apps
{
/** The fields of the robot's report @p replay that differ from @p original (paths like
 * `robot.path[12].estimate`), leaving out wall-clock times (compute, rendering), the links'
 * counters, the replay's own fields and what eval fills in (null in the robot's report). At most
 * @p max_listed paths are listed; the count of all differences is the last entry when more. */
std::vector<std::string> reportDifferences(const nlohmann::json& original,
                                           const nlohmann::json& replay, size_t max_listed = 20);

}  // namespace mrolr::apps
