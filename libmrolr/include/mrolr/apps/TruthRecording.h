#pragma once
/** The world side's truth in a rawlog (GROUND_TRUTH), written beside what the robot recorded: by
 * mrolr-mission from its in-process lab after each base step, by `mrolr-serial emulate` at its end
 * beside T.json. Only eval reads it back, to recheck a replayed run. */
#include <mrolr/io/ObservationLog.h>
#include <mrolr/sim/Lab.h>

#include <functional>
#include <string>
#include <vector>

namespace mrolr::apps
{
/** The lab's latest true vehicle pose as a CObservationRobotPose labelled `GROUND_TRUTH` (MRPT
 * axes: x = z, y = x, yaw = φ; stamped 1.7e9 s + the base's time; null before the first): the
 * world side's record after each base step, which a replay never reads. */
std::function<mrpt::obs::CObservation::Ptr()> truthRecorder(const sim::Lab& lab);

/** Every true step the lab logged, as GROUND_TRUTH records, into a new rawlog at @p path. */
void writeTruthRawlog(const sim::Lab& lab, const std::string& path);

/** The true steps a rawlog holds (its GROUND_TRUTH records), for eval after a replay. */
std::vector<sim::TruthLog::Step> recordedTruthSteps(const std::string& rawlog_path);

}  // namespace mrolr::apps
