#pragma once
/** A run's outputs in out/<mission>-<timestamp>/ (docs/mission.md "Outputs"): report.json,
 * report.md, trajectory.png and mission.3Dscene (mission.rawlog is written while the mission runs,
 * mission/DeviceRecorder.h). The robot's part comes from
 * mission::reportJson; estimate.tum, odometry.tum (and truth.tum with the truth) hold the paths
 * in the TUM format. With the world's truth (in-process runs) eval adds its checks, the true
 * path, the room and the objects to the pictures. Without
 * it (the robot in its own process) the pictures show what the robot knew. */
#include <mrolr/eval/MissionTruth.h>
#include <mrolr/mission/Mission.h>

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace mrolr::eval
{
struct WrittenOutputs
{
	std::vector<std::string> files;
	nlohmann::json report;  ///< report.json as written
};

/** Top view: the plan's tables, the mapped landmarks, the estimated and dead-reckoned paths, a
 * collision; with @p truth also the room, obstacles, true landmarks, the true path and the
 * objects. */
void writeTrajectoryPng(const mission::MissionResult& r, const mission::MissionOptions& o,
                        const MissionTruth* truth, const std::string& path);
/** The room (with truth) or the plan's tables, the paths, the map with 95 % ellipsoids, the
 * recognised model where the robot believed it was, and the arm at its grasp (.3Dscene). */
void writeScene3D(const mission::MissionResult& r, const mission::MissionOptions& o,
                  const MissionTruth* truth, const std::string& path);
/** The trajectories in the TUM format (io/TumTrajectory.h), stamped with the base's clock:
 * estimate.tum and odometry.tum, and with an in-process @p truth truth.tum, so that
 * `evo_ape tum truth.tum estimate.tum` compares them. Returns the files written. */
std::vector<std::string> writeTumTrajectories(const mission::MissionResult& r,
                                              const MissionTruth* truth, const std::string& dir);
/** Writes everything into @p dir (created); evaluates the report when @p truth is given. */
WrittenOutputs writeMissionOutputs(const mission::MissionResult& r,
                                   const mission::MissionOptions& o, const MissionTruth* truth,
                                   const std::string& dir);

}  // namespace mrolr::eval
