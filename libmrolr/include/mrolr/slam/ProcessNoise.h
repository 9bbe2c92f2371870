#pragma once
/** @file Process noise Q of the Labmate model (thesis eq 5.12) to first or second order. */

#include <mrolr/base/LabmateModel.h>

#include <Eigen/Core>

namespace mrolr::slam
{
/** Second-order part of the covariance of f(x_v, u + w), w ~ N(0, U), U the model's control
 * covariance (eq 5.13): Q₂(a, b) = ½ tr(H_a U H_b U), H_a the Hessian of output a of the motion
 * model with respect to the wheel velocities (v1, v2), by central differences. Exact for the
 * s·θ cross terms of the model, which the first-order Q = ∇f_u U ∇f_uᵀ misses: with 14 % wheel
 * noise they are larger than the lateral uncertainty the first-order Q leaves after a heading
 * measurement. Units: m², m·rad, rad² in (z, x, φ) of the world frame W. */
Eigen::Matrix3d secondOrderProcessNoise(const base::LabmateModel& model, const Eigen::Vector3d& x_v,
                                        const base::WheelControl& u);

}  // namespace mrolr::slam
