#pragma once
/** The midpoint of the common perpendicular of two rays (thesis 4.2.5, eqs 4.45–4.50), the
 * estimate of a point seen along two rays that, because of noise, do not meet. Frame-free: all
 * vectors in one frame, any length unit. */

#include <mrolr/geometry/GeometryError.h>

#include <Eigen/Core>

namespace mrolr::geometry
{
/** The closest approach of ray 1 = a + λ·u1 and ray 2 = c + μ·u2 (u1, u2 unit). */
struct RayMidpoint
{
	Eigen::Vector3d point = Eigen::Vector3d::Zero();  ///< midpoint of the common perpendicular
	double lambda = 0;     ///< distance along ray 1 to its foot of the perpendicular (eq 4.49)
	double mu = 0;         ///< distance along ray 2 to its foot of the perpendicular
	double gap = 0;        ///< length of the common perpendicular, d12 (eq 4.48), ≥ 0
	double sin_angle = 0;  ///< sin ψ, ψ the angle between the rays
};

/** Default for the smallest accepted sin ψ: 1e-4 rad between the rays, i.e. a point 2.5 km away
 * for a 0.25 m baseline; closer to parallel, the midpoint is numerically meaningless. */
constexpr double kMinRaySinAngle = 1e-4;

/** Midpoint of the common perpendicular between the rays from @p a along @p b and from @p c along
 * @p d (directions need not be unit), eq 4.50: m = ([u1]² + [u2]²)⁻¹ ([u1]² a + [u2]² c).
 * Throws TriangulationError if sin ψ < @p min_sin_angle (near-parallel rays). */
RayMidpoint midpointOfCommonPerpendicular(const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                                          const Eigen::Vector3d& c, const Eigen::Vector3d& d,
                                          double min_sin_angle = kMinRaySinAngle);

/** ∂m/∂(b, d), the 3×6 Jacobian of the midpoint @p m (as returned for the same rays) with respect
 * to the two un-normalised ray directions; the ray origins are held fixed. */
Eigen::Matrix<double, 3, 6> midpointJacobianWrtDirections(const Eigen::Vector3d& a,
                                                          const Eigen::Vector3d& b,
                                                          const Eigen::Vector3d& c,
                                                          const Eigen::Vector3d& d,
                                                          const Eigen::Vector3d& m);

}  // namespace mrolr::geometry
