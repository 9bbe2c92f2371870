#include <mrolr/geometry/RayTriangulation.h>

#include <Eigen/Geometry>
#include <Eigen/LU>

#include <sstream>

namespace mrolr::geometry
{
namespace
{
// [u]² = u uᵀ − I for a unit u (the identity under eq 4.50): minus the projector onto u's normal
// plane.
Eigen::Matrix3d skewSquared(const Eigen::Vector3d& u)
{
	return u * u.transpose() - Eigen::Matrix3d::Identity();
}

// ∂P/∂b_k · w for P(b) = I − b bᵀ / (bᵀb), the normal-plane projector of an un-normalised b.
Eigen::Vector3d projectorDerivativeTimes(const Eigen::Vector3d& b, int k, const Eigen::Vector3d& w)
{
	const double bb = b.squaredNorm(), bw = b.dot(w);
	Eigen::Vector3d r = -(bw / bb) * Eigen::Vector3d::Unit(k) - (w[k] / bb) * b;
	return r + (2 * b[k] * bw / (bb * bb)) * b;
}
}  // namespace

RayMidpoint midpointOfCommonPerpendicular(const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                                          const Eigen::Vector3d& c, const Eigen::Vector3d& d,
                                          double min_sin_angle)
{
	const Eigen::Vector3d u1 = b.normalized(), u2 = d.normalized();  // eqs 4.45, 4.46
	const Eigen::Vector3d cross = u1.cross(u2);
	RayMidpoint r;
	r.sin_angle = cross.norm();
	if (!(r.sin_angle >= min_sin_angle))
	{
		std::ostringstream msg;
		msg << "rays are near-parallel (angle " << r.sin_angle << " rad < " << min_sin_angle
		    << " rad): the point is too far to triangulate";
		throw TriangulationError(msg.str());
	}
	const Eigen::Vector3d u3 = cross / r.sin_angle;
	Eigen::Matrix3d M;
	M << u1, -u2, u3;
	const Eigen::Vector3d lmd = M.partialPivLu().solve(c - a);  // eq 4.49: (λ, μ, d12)
	r.lambda = lmd[0];
	r.mu = lmd[1];
	r.gap = std::abs(lmd[2]);
	const Eigen::Matrix3d S1 = skewSquared(u1), S2 = skewSquared(u2);
	r.point = (S1 + S2).partialPivLu().solve(S1 * a + S2 * c);  // eq 4.50
	return r;
}

Eigen::Matrix<double, 3, 6> midpointJacobianWrtDirections(const Eigen::Vector3d& a,
                                                          const Eigen::Vector3d& b,
                                                          const Eigen::Vector3d& c,
                                                          const Eigen::Vector3d& d,
                                                          const Eigen::Vector3d& m)
{
	// m = A⁻¹ (P1 a + P2 c) with A = P1 + P2, so dm = A⁻¹ (dP1 (a − m) + dP2 (c − m)).
	const Eigen::Matrix3d P1 = -skewSquared(b.normalized()), P2 = -skewSquared(d.normalized());
	const auto Ainv = (P1 + P2).partialPivLu();
	Eigen::Matrix<double, 3, 6> J;
	for (int k = 0; k < 3; ++k)
	{
		J.col(k) = Ainv.solve(projectorDerivativeTimes(b, k, a - m));
		J.col(3 + k) = Ainv.solve(projectorDerivativeTimes(d, k, c - m));
	}
	return J;
}

}  // namespace mrolr::geometry
