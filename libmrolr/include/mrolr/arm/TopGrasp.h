#pragma once
/** The alternative grasp of thesis 6.6.1: only the translation is taken from recognition, as the
 * centroid of the matched scene segments' centre points (line midpoints, conic centres), and every
 * object is picked from the top with a wide-opening gripper. */

#include <mrolr/arm/GripperPose.h>
#include <mrolr/model/WireFrame.h>

#include <Eigen/Core>

#include <vector>

namespace mrolr::arm
{
/** Centroid = (1/n) Σ mᵢ of the n centre points (6.6.1), in the segments' frame. Throws
 * std::invalid_argument when there is no segment. */
Eigen::Vector3d segmentCentroid(const std::vector<model::Line3>& lines,
                                const std::vector<model::Conic3>& conics);

/** Top grasp in the segments' frame F (normally the arm base A, z up): position the centroid,
 * pitch 90° (approach straight down), roll 0, and the yaw in [0°, 180°) (1° steps) whose closing
 * axis y_G meets the narrowest horizontal extent of the segments' sampled points. */
GripperPose topGrasp(const std::vector<model::Line3>& lines,
                     const std::vector<model::Conic3>& conics);

}  // namespace mrolr::arm
