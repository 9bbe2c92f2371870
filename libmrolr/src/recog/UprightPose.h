#pragma once
// Poses of objects standing upright on the support plane, shared by the plane hypotheses
// (PlaneHypotheses.cpp, PlaneLimbHypotheses.cpp). Internal header.
#include <mrolr/recog/plane/SupportPlane.h>

#include <Eigen/Core>

#include <cmath>
#include <utility>

namespace mrolr::recog::detail
{
/** Two horizontal unit vectors (h1, h2 = n × h1) completing the plane's normal to a right-handed
 * basis. */
inline std::pair<Eigen::Vector3d, Eigen::Vector3d> horizontalBasis(const Eigen::Vector3d& n)
{
	Eigen::Vector3d a = Eigen::Vector3d::UnitX();
	if (std::abs(n.x()) > 0.9) a = Eigen::Vector3d::UnitZ();
	const Eigen::Vector3d h1 = (a - a.dot(n) * n).normalized();
	return {h1, n.cross(h1)};
}

/** The rotation taking the model's +z to @p n and its +x to the horizontal direction at angle
 * @p yaw from h1 (towards h2). */
inline Eigen::Matrix3d uprightRotation(const Eigen::Vector3d& n, double yaw)
{
	const auto [h1, h2] = horizontalBasis(n);
	Eigen::Matrix3d R;
	R.col(0) = std::cos(yaw) * h1 + std::sin(yaw) * h2;
	R.col(1) = -std::sin(yaw) * h1 + std::cos(yaw) * h2;
	R.col(2) = n;
	return R;
}

/** @p t with its component along the plane's normal set so that the model's base (z = base_z)
 * lies in the plane: n·(R (x, y, base_z) + t) + d = 0 with R z = n. */
inline Eigen::Vector3d standOn(Eigen::Vector3d t, const SupportPlane& plane, double base_z_mm)
{
	return t + (-plane.d_mm - base_z_mm - plane.n_S.dot(t)) * plane.n_S;
}

}  // namespace mrolr::recog::detail
