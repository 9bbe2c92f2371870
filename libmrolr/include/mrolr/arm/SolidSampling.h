#pragma once
/** The object as the gripper meets it, from its wire-frame model: the edge samples of
 * sampleWireFrame (GraspFeasibility.h) and, between consecutive coaxial full circles (the rims of
 * a can, a bottle or a cup's body), the surface of revolution that joins them, sampled as circles
 * every @p step_mm along the axis with the radius interpolated. A turntable-built can has only its
 * rims; the grasp checks need the body between them (thesis 6.6: the grasp closes on the body). */
#include <mrolr/model/WireFrame.h>

#include <Eigen/Geometry>
#include <vector>

namespace mrolr::arm
{
/** Points of @p wf's edges and surfaces of revolution, moved by @p T (mm). */
std::vector<Eigen::Vector3d> sampleSolid(const model::WireFrame& wf, const Eigen::Isometry3d& T,
                                         double step_mm);

/** The surfaces of revolution alone: for each pair of consecutive coaxial full circles (normals
 * within 2.5 deg, centres within @p axis_tol_mm of one axis), circles every @p step_mm. */
std::vector<Eigen::Vector3d> sampleRevolutionSurfaces(const model::WireFrame& wf,
                                                      const Eigen::Isometry3d& T, double step_mm,
                                                      double axis_tol_mm = 3.0);

}  // namespace mrolr::arm
