#pragma once
/** What mrolr-mission adds to a run's recording from the world side, and how it checks a replay
 * against the run it replays (docs/mission.md "Recording and replay"). */
#include <mrolr/io/ObservationLog.h>
#include <mrolr/sim/Lab.h>

#include <nlohmann/json.hpp>

#include <functional>
#include <string>
#include <vector>

namespace mrolr::apps
{
/** Writes the lab's true vehicle pose after each base step as a CObservationRobotPose labelled
 * `GROUND_TRUTH` (MRPT axes: x = z, y = x, yaw = φ): the world side's record, which a replay never
 * reads. */
std::function<void(io::ObservationLogWriter&)> truthRecorder(const sim::Lab& lab);

/** The true steps a recording holds (its GROUND_TRUTH records), for eval after a replay. */
std::vector<sim::TruthLog::Step> recordedTruthSteps(const std::string& rawlog_path);

/** The fields of the robot's report @p replay that differ from @p original (paths like
 * `robot.path[12].estimate`), leaving out wall-clock times (compute, rendering), the links'
 * counters, the replay's own fields and what eval fills in (null in the robot's report). At most
 * @p max_listed paths are listed; the count of all differences is the last entry when more. */
std::vector<std::string> reportDifferences(const nlohmann::json& original,
                                           const nlohmann::json& replay, size_t max_listed = 20);

}  // namespace mrolr::apps
