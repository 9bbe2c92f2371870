// Midpoint of the common perpendicular (thesis eqs 4.45–4.50) against a direct construction.
#include <mrolr/geometry/RayTriangulation.h>

#include "geometry_test_util.h"

#include <gtest/gtest.h>

#include <Eigen/Dense>

using namespace mrolr::geometry;

namespace
{
Eigen::Vector3d randomVector(std::mt19937& rng)
{
	std::uniform_real_distribution<double> d(-2, 2);
	return {d(rng), d(rng), d(rng)};
}
}  // namespace

TEST(RayTriangulation, MidpointIsHalfwayBetweenTheClosestPoints)
{
	std::mt19937 rng(9);
	for (int k = 0; k < 200; ++k)
	{
		const Eigen::Vector3d a = randomVector(rng), b = randomVector(rng);
		const Eigen::Vector3d c = randomVector(rng), d = randomVector(rng);
		// Closest points by least squares on (s, t): min |a + s b − c − t d|².
		Eigen::Matrix<double, 3, 2> A;
		A << b, -d;
		const Eigen::Vector2d st = A.colPivHouseholderQr().solve(c - a);
		const Eigen::Vector3d p1 = a + st[0] * b, p2 = c + st[1] * d;
		const RayMidpoint r = midpointOfCommonPerpendicular(a, b, c, d, 1e-9);
		EXPECT_TRUE(r.point.isApprox((p1 + p2) / 2, 1e-9));
		EXPECT_NEAR(r.gap, (p1 - p2).norm(), 1e-9);
		EXPECT_NEAR(r.lambda, st[0] * b.norm(), 1e-9);
		EXPECT_NEAR(r.mu, st[1] * d.norm(), 1e-9);
		// The common perpendicular is perpendicular to both rays.
		EXPECT_NEAR((p2 - p1).dot(b), 0, 1e-9);
		EXPECT_NEAR((p2 - p1).dot(d), 0, 1e-9);
	}
}

TEST(RayTriangulation, DirectionJacobianMatchesCentralDifferences)
{
	std::mt19937 rng(10);
	for (int k = 0; k < 100; ++k)
	{
		const Eigen::Vector3d a = randomVector(rng), c = randomVector(rng);
		Eigen::Matrix<double, 6, 1> bd;
		bd << randomVector(rng), randomVector(rng);
		const auto f = [&](const Eigen::Matrix<double, 6, 1>& x)
		{ return midpointOfCommonPerpendicular(a, x.head<3>(), c, x.tail<3>(), 1e-9).point; };
		const auto num = test_util::numericJacobian<3, 6>(f, bd, 1e-6);
		const Eigen::Matrix<double, 3, 6> J =
		    midpointJacobianWrtDirections(a, bd.head<3>(), c, bd.tail<3>(), f(bd));
		EXPECT_LT((J - num).cwiseAbs().maxCoeff(), 1e-5 * (1 + num.cwiseAbs().maxCoeff()));
	}
}

TEST(RayTriangulation, NearParallelRaysAreRejectedWithTheAngle)
{
	const Eigen::Vector3d a(0, 0, 0), c(1, 0, 0), b(0, 0, 1);
	EXPECT_NO_THROW(midpointOfCommonPerpendicular(a, b, c, Eigen::Vector3d(-1e-3, 0, 1)));
	try
	{
		midpointOfCommonPerpendicular(a, b, c, Eigen::Vector3d(-1e-5, 0, 1));
		FAIL() << "expected TriangulationError";
	}
	catch (const TriangulationError& e)
	{
		EXPECT_NE(std::string(e.what()).find("near-parallel"), std::string::npos) << e.what();
	}
}
