#pragma once
/** The object pose from recognition, in the left camera frame L, moved to the head centre C0 with
 * the BiSight head model (thesis 6.6, eq 4.3.6): T_OinC0 = T_LinC0(angles) · T_OinL. */

#include <mrolr/geometry/BiSightHead.h>

#include <Eigen/Geometry>

namespace mrolr::arm
{
/** @p T_OinL_mm: the object in the left camera (thesis axes, mm); the head works in metres, the
 * result is in mm. */
Eigen::Isometry3d objectInHeadCentre(const geometry::BiSightHead& head,
                                     const geometry::HeadAngles& angles,
                                     const Eigen::Isometry3d& T_OinL_mm);

}  // namespace mrolr::arm
