#pragma once
/** The measurement model of the active-vision EKF (thesis 5.5.4–5.5.6): a 3D point feature y_i in
 * W measured by an ideal head at the head centre C0 of a vehicle at x_v = (z, x, φ).
 *
 * Point relative to the head (eq 5.35), with y_i = (X, Y, Z) in W (x left, y up, z forward):
 *   m_x = (X − x) cos φ − (Z − z) sin φ,   m_y = Y − M_h,   m_z = (X − x) sin φ + (Z − z) cos φ,
 * i.e. m_GinC0 = R_y(φ)ᵀ (y_i − (x, M_h, z)); the measurement is h = (pan, elevation, vergence) of
 * the ideal head (eq 5.40, mrolr/geometry/IdealHead.h). Its inverse (eq 5.46) initialises features:
 *   X = x + m_x cos φ + m_z sin φ,   Y = M_h + m_y,   Z = z − m_x sin φ + m_z cos φ. */

#include <Eigen/Core>

namespace mrolr::slam
{
/** The two head constants the filter needs (config/bisight.ini keys interocular_m, head_height_m).
 */
struct HeadConstants
{
	double interocular_m = 0.25;  ///< I, eq 5.40
	double head_height_m = 1.0;   ///< M_h, height of C0 above the ground plane (eqs 5.35, 5.50)
};

/** m_GinC0 of eq 5.35 (metres, C0 axes). */
Eigen::Vector3d pointInHead(const Eigen::Vector3d& x_v, const Eigen::Vector3d& p_FinW,
                            const HeadConstants& head);

/** ∂m_GinC0/∂x_v and ∂m_GinC0/∂y_i = R_y(φ)ᵀ (also the Jacobians of frame zeroing, eq 5.51). */
struct PointInHeadJacobians
{
	Eigen::Matrix3d dm_dxv;
	Eigen::Matrix3d dm_dy;
};
PointInHeadJacobians pointInHeadJacobians(const Eigen::Vector3d& x_v, const Eigen::Vector3d& p_FinW,
                                          const HeadConstants& head);

/** h(x_v, y_i) = (pan, elevation, vergence) in rad (eqs 5.35 + 5.40). */
Eigen::Vector3d predictMeasurement(const Eigen::Vector3d& x_v, const Eigen::Vector3d& p_FinW,
                                   const HeadConstants& head);

/** ∂h/∂x_v and ∂h/∂y_i, both 3×3 (analytic). */
struct MeasurementJacobians
{
	Eigen::Matrix3d H_xv;
	Eigen::Matrix3d H_y;
};
MeasurementJacobians measurementJacobians(const Eigen::Vector3d& x_v, const Eigen::Vector3d& p_FinW,
                                          const HeadConstants& head);

/** y_i from a first measurement h at pose x_v (eq 5.46), and its Jacobians ∂y/∂x_v, ∂y/∂h used
 * for the new covariance blocks (eq 5.48). */
struct FeatureInitialisation
{
	Eigen::Vector3d p_FinW;
	Eigen::Matrix3d dy_dxv;
	Eigen::Matrix3d dy_dh;
};
FeatureInitialisation initialiseFromMeasurement(const Eigen::Vector3d& x_v,
                                                const Eigen::Vector3d& h,
                                                const HeadConstants& head);

/** z − h with every angle difference wrapped into (−π, π]. */
Eigen::Vector3d measurementDifference(const Eigen::Vector3d& z, const Eigen::Vector3d& h);

/** Position of the head centre C0 in W for vehicle pose x_v: (x, M_h, z). */
Eigen::Vector3d headCentreInW(const Eigen::Vector3d& x_v, const HeadConstants& head);

}  // namespace mrolr::slam
