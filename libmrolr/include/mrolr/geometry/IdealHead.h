#pragma once
/** The angular measurement of an ideal active head at the head centre C0 (thesis eq 5.40): the pan,
 * elevation and vergence a head with zero offsets would need to fixate a point. The EKF measures
 * features in these angles because their noise is well modelled by a constant diagonal R (eq 5.41). */

#include <Eigen/Core>

namespace mrolr::geometry
{
/** h = (pan α, elevation e, vergence γ) in radians of the point m_G, given in C0 (x left, y up,
 * z forward, metres), for interocular separation I in metres (eq 5.40):
 *   α = atan2(m_x, m_z),  e = atan2(m_y, sqrt(m_x² + m_z²)),  γ = atan(I / (2 |m_G|)).
 * γ is the (positive) angle each camera turns inwards. Throws std::invalid_argument for |m_G| = 0. */
Eigen::Vector3d idealHeadMeasure(const Eigen::Vector3d& p_GinC0, double interocular_m);

/** ∂h/∂m_G, the 3×3 Jacobian of idealHeadMeasure with respect to the point (analytic).
 * Throws std::invalid_argument on the pan axis (m_x = m_z = 0), where pan is undefined. */
Eigen::Matrix3d idealHeadJacobian(const Eigen::Vector3d& p_GinC0, double interocular_m);

/** The point in C0 that an ideal head with angles h fixates: the inverse of idealHeadMeasure,
 * with |m_G| = I / (2 tan γ). Throws std::invalid_argument unless 0 < γ < π/2. */
Eigen::Vector3d idealHeadInverse(const Eigen::Vector3d& h, double interocular_m);

/** ∂m_G/∂h, the Jacobian of idealHeadInverse (used to initialise a feature's covariance, eq 5.48). */
Eigen::Matrix3d idealHeadInverseJacobian(const Eigen::Vector3d& h, double interocular_m);

}  // namespace mrolr::geometry
