#pragma once
/** The wheel control that explains an odometry increment, for replaying recorded odometry through
 * the Labmate model (thesis 4.2.6, eqs 5.1–5.7). */

#include <mrolr/base/LabmateModel.h>

#include <Eigen/Core>

namespace mrolr::apps
{
/** The control u = (v1, v2, dt) under which the Labmate model moves @p from to @p to (both
 * (z, x, φ) in W, metres and radians) along one circular arc in @p dt_s seconds, so that
 * LabmateModel::move(from, u) = to for any increment that is such an arc (rotations in place and
 * straight moves included); otherwise the arc whose end is nearest. @p wheel_half_separation_m is
 * D1. Throws std::invalid_argument unless dt_s > 0. */
base::WheelControl controlFromOdometry(const Eigen::Vector3d& from, const Eigen::Vector3d& to,
                                       double dt_s, double wheel_half_separation_m);

}  // namespace mrolr::apps
