#pragma once
// Shared helpers of the geometry tests: central-difference Jacobians and random head states.

#include <mrolr/geometry/BiSightHead.h>

#include <Eigen/Core>

#include <cmath>
#include <random>

namespace mrolr::geometry::test_util
{
/** Central differences of f: R^n -> R^m at x. */
template <int M, int N, class F>
Eigen::Matrix<double, M, N> numericJacobian(F f, const Eigen::Matrix<double, N, 1>& x, double h)
{
	Eigen::Matrix<double, M, N> J;
	for (int i = 0; i < N; ++i)
	{
		Eigen::Matrix<double, N, 1> a = x, b = x;
		a[i] += h;
		b[i] -= h;
		J.col(i) = (f(a) - f(b)) / (2 * h);
	}
	return J;
}

/** Head options with every offset non-zero and distinct, and a principal point off the image
 * centre, so that a swapped offset or axis cannot pass a test. */
inline BiSightOptions offsetTestOptions()
{
	BiSightOptions o;
	o.interocular_m = 0.25;
	o.pan_offset_m = 0.031;
	o.tilt_offset_m = 0.052;
	o.optic_offset_m = 0.067;
	o.focal_px_u = 801;
	o.focal_px_v = 807;
	o.u0_px = 318.5;
	o.v0_px = 244.25;
	return o;
}

/** A point in front of the head within the default joint limits: 0.6–6 m away, azimuth ±60°,
 * elevation ±35° (C0, metres). */
inline Eigen::Vector3d randomPointAhead(std::mt19937& rng)
{
	std::uniform_real_distribution<double> dist(0.6, 6), az(-1.05, 1.05), el(-0.6, 0.6);
	const double r = dist(rng), a = az(rng), e = el(rng);
	return r * Eigen::Vector3d(std::cos(e) * std::sin(a), std::sin(e), std::cos(e) * std::cos(a));
}

/** Head angles that roughly look at @p p but are perturbed, so the point is not fixated. */
inline HeadAngles randomAnglesLookingNear(const BiSightHead& head, const Eigen::Vector3d& p,
                                          std::mt19937& rng)
{
	std::uniform_real_distribution<double> d(-0.08, 0.08);
	HeadAngles a = head.fixate(p);
	a.pan += d(rng);
	a.tilt += d(rng);
	a.verg_left += d(rng) / 4;
	a.verg_right += d(rng) / 4;
	return a;
}

}  // namespace mrolr::geometry::test_util
