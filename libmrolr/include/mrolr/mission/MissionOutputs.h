#pragma once
/** The robot's report of a run (docs/mission.md "Outputs"): what it did and what it believes, in
 * report.json's form. eval adds the truth checks to the same document (eval/MissionEval.h); the
 * pictures and the recording are eval::writeMissionOutputs. */
#include <mrolr/mission/Mission.h>

#include <nlohmann/json.hpp>

#include <string>

namespace mrolr::mission
{
/** report.json's robot content: success (the robot's claim), failure, target, found, retrieved,
 * returned_home (its estimate), the robot's beliefs under `robot` (final estimate and its
 * covariance, home, jaw width, recognised pose, grasp, the path with covariances, the map),
 * navigation and recognition figures, per-stage times, the NIS of every update and the timeline.
 * The truth fields (final_position_error_m, object_*_error_*) are null until eval fills them. */
nlohmann::json reportJson(const MissionResult& r, const MissionOptions& o);
/** A human-readable report.md of a report.json (robot and, when present, eval fields). */
std::string reportMarkdown(const nlohmann::json& report);
/** Rows of [R | t] of a transform, as report.json writes them; and back (throws
 * std::invalid_argument for a malformed value). */
nlohmann::json matrix34(const Eigen::Isometry3d& T);
Eigen::Isometry3d isometryFrom(const nlohmann::json& rows);

}  // namespace mrolr::mission
