#pragma once
/** The mission's outputs in out/<mission>-<timestamp>/ (docs/mission.md "Outputs"): report.json,
 * report.md, trajectory.png, mission.3Dscene and mission.rawlog. */
#include <mrolr/mission/Mission.h>

#include <nlohmann/json.hpp>

#include <string>

namespace mrolr::mission
{
/** report.json's content: success, target, found, retrieved, returned_home,
 * final_position_error_m, object_rotation_error_deg, object_translation_error_mm,
 * grasp_correction_mm, stages (name → simulated seconds), compute_seconds, simulated_seconds,
 * T_OinA, grasp pose, joint solution, timeline and more. Unavailable numbers are null. */
nlohmann::json reportJson(const MissionResult& r, const MissionOptions& o);
/** A human-readable report.md of the same content. */
std::string reportMarkdown(const MissionResult& r, const MissionOptions& o);
/** Top view of the room: table, landmarks (true and mapped), true / estimated / dead-reckoned
 * paths; written as PNG. */
void writeTrajectoryPng(const MissionResult& r, const MissionOptions& o, const std::string& path);
/** The room with the true and estimated paths, the map with 95 % ellipsoids, the recognised model
 * placed where it was recognised, and the arm at its grasp pose (mrpt::opengl .3Dscene). */
void writeScene3D(const MissionResult& r, const MissionOptions& o, const std::string& path);
/** The run as an MRPT rawlog through io::RawlogWriter: odometry and ground truth per step, and the
 * sweeps' stereo pairs (images in <name>_Images/) in time order. */
void writeRawlog(const MissionResult& r, const MissionOptions& o, const std::string& path);
/** Writes every output into @p dir (created); returns the files written. */
std::vector<std::string> writeOutputs(const MissionResult& r, const MissionOptions& o,
                                      const std::string& dir);

}  // namespace mrolr::mission
