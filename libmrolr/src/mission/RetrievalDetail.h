#pragma once
// Helpers shared by the retrieval's sources (private to the mission area).
#include <Eigen/Geometry>

#include <cmath>

namespace mrolr::mission::detail
{
/** The rotation between two poses' orientations (deg). */
inline double angleBetweenDeg(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b)
{
	return Eigen::AngleAxisd(a.linear().transpose() * b.linear()).angle() * 180.0 / M_PI;
}
}  // namespace mrolr::mission::detail
