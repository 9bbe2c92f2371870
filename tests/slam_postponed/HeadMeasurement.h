#pragma once
// The angular measurement of feature y_i from vehicle pose x_v used by the postponed-update tests:
// the feature in C0 (thesis eq 5.35, head centre at the vehicle's (z, x) at the height of W's
// origin) measured by the ideal head of eq 5.40 (mrolr::geometry::idealHeadMeasure).

#include <Eigen/Core>

namespace mrolr::slam::test
{
/** p_FinC0 = R_C0fromW(φ) (y − (x, 0, z)) for x_v = (z, x, φ), y = (X, Y, Z) in W (eq 5.35). */
Eigen::Vector3d featureInC0(const Eigen::Vector3d& x_v, const Eigen::Vector3d& y);

/** h(x_v, y) = (pan, elevation, vergence) in rad (eq 5.40). */
Eigen::Vector3d headMeasure(const Eigen::Vector3d& x_v, const Eigen::Vector3d& y, double I_m);

/** (∂h/∂x_v, ∂h/∂y), 3×6, analytic (chain rule through eq 5.35). */
Eigen::Matrix<double, 3, 6> headJacobian(const Eigen::Vector3d& x_v, const Eigen::Vector3d& y,
                                         double I_m);

}  // namespace mrolr::slam::test
