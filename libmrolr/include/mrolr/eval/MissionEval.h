#pragma once
/** eval: the robot's report checked against the world's truth, after the run (DESIGN.md
 * "eval"). Fills report.json's truth fields and its `eval` object:
 *  - the true home error (final_position_error_m, final_heading_error_deg), the estimate's and the
 *    odometry's errors there (final_estimate_error_m, dead_reckoning_error_m);
 *  - whether the robot really has the target: in its gripper (`eval.object_held`) or on its deck
 *    (`eval.object_on_board`), either being `eval.object_retrieved`;
 *  - which object was recognised and the pose errors (object_translation_error_mm,
 *    object_rotation_error_deg; in C0 at the recognising frame when the frames' truth is known,
 *    else in W from the robot's own pose estimate), the retrieval's errors and grasp error;
 *  - the vehicle's NEES along the path when every step's truth is known;
 *  - a collision (what was hit and where).
 * `success` becomes true only when the robot claimed success and eval confirms it. */
#include <mrolr/eval/MissionTruth.h>

#include <nlohmann/json.hpp>

namespace mrolr::eval
{
/** Adds the truth checks to @p report (a report.json written by mission::reportJson). Throws
 * std::runtime_error naming the field when the report lacks one it needs. */
void evaluateMission(nlohmann::json& report, const MissionTruth& truth);

}  // namespace mrolr::eval
