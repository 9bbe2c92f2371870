#pragma once
// mrolr-slam --out DIR, MRPT files: decisions.rawlog (the filter's decisions, readable by
// RawLogViewer and rawlog-edit) and slam.3Dscene (map, 95 % ellipsoids, paths; SceneViewer3D).
#include <mrolr/apps/SlamApp.h>

#include <string>

namespace mrolr::apps
{
/** The one-line text of a decision (format in docs/vision.md, "decisions.rawlog"). */
std::string decisionText(size_t step, const vision::CycleRecord& r);

/** One (CActionCollection, CSensoryFrame) pair per step: the dead-reckoned motion as
 * CActionRobotMovement2D; CObservationComment "SLAM_DECISION" per record; CObservationRobotPose
 * "SLAM_ESTIMATE" (mean and covariance) and "GROUND_TRUTH". Throws naming @p path on failure. */
void writeDecisionRawlog(const std::string& path, const std::vector<SlamStepLog>& steps);

/** The map (CEllipsoid3D at 95 %, known features green, others red), the true landmarks (black
 * points), and the true (green), estimated (red) and dead-reckoned (blue) paths, MRPT axes. */
void writeSlamScene(const std::string& path, const std::vector<SlamStepLog>& steps,
                    const std::vector<MapFeature>& map, const std::vector<TrueLandmark>& truth);

}  // namespace mrolr::apps
