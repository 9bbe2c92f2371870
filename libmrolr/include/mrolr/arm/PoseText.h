#pragma once
/** The 12-number text form of a rigid transform used by mrolr-arm: the rows of the 3×4 matrix
 * [R | t], "r11,r12,r13,tx,r21,r22,r23,ty,r31,r32,r33,tz", translation in mm. */

#include <Eigen/Geometry>

#include <string>
#include <vector>

namespace mrolr::arm
{
/** Builds a pose from 12 numbers. The rotation must be orthonormal with determinant +1 within
 * @p tolerance (the thesis prints 0.707 for 1/√2, hence the default 2e-3); it is then replaced by
 * the nearest rotation (SVD). Throws PoseInputError naming @p what and the defect. */
Eigen::Isometry3d poseFrom12(const std::vector<double>& v, const std::string& what,
                             double tolerance = 2e-3);

/** Parses "a,b,...,l" (12 numbers) with poseFrom12. */
Eigen::Isometry3d parsePose12(const std::string& text, const std::string& what);

/** The 12 numbers of @p T, row by row. */
std::vector<double> poseTo12(const Eigen::Isometry3d& T);

}  // namespace mrolr::arm
