#include <mrolr/geometry/IdealHead.h>

#include "geometry_test_util.h"

#include <gtest/gtest.h>

#include <random>

using namespace mrolr::geometry;
using mrolr::geometry::test_util::numericJacobian;

namespace
{
constexpr double kI = 0.25;

Eigen::Vector3d randomPoint(std::mt19937& rng)
{
	std::uniform_real_distribution<double> lat(-3, 3), up(-1, 2.5), fwd(0.3, 6);
	return {lat(rng), up(rng), fwd(rng)};
}
}  // namespace

TEST(IdealHead, AnglesHaveTheirGeometricMeaning)
{
	// Straight ahead at 2 m: no pan, no elevation, vergence atan(0.125 / 2).
	const auto h = idealHeadMeasure({0, 0, 2}, kI);
	EXPECT_NEAR(h[0], 0, 1e-15);
	EXPECT_NEAR(h[1], 0, 1e-15);
	EXPECT_NEAR(h[2], std::atan(0.0625), 1e-15);
	// To the left (x > 0) is positive pan; up (y > 0) is positive elevation.
	EXPECT_NEAR(idealHeadMeasure({1, 0, 1}, kI)[0], M_PI / 4, 1e-15);
	EXPECT_NEAR(idealHeadMeasure({0, 1, 1}, kI)[1], M_PI / 4, 1e-15);
	// Behind the head the pan is beyond ±90°.
	EXPECT_GT(std::abs(idealHeadMeasure({0.1, 0, -1}, kI)[0]), M_PI / 2);
	EXPECT_THROW(idealHeadMeasure({0, 0, 0}, kI), std::invalid_argument);
}

TEST(IdealHead, JacobiansMatchCentralDifferences)
{
	std::mt19937 rng(7);
	for (int k = 0; k < 200; ++k)
	{
		const Eigen::Vector3d m = randomPoint(rng);
		const auto num =
		    numericJacobian<3, 3>(
		    [](const Eigen::Vector3d& x) { return idealHeadMeasure(x, kI); }, m, 1e-6);
		EXPECT_LT((idealHeadJacobian(m, kI) - num).cwiseAbs().maxCoeff(), 1e-7) << m.transpose();
		const Eigen::Vector3d h = idealHeadMeasure(m, kI);
		const auto numInv = numericJacobian<3, 3>(
		    [](const Eigen::Vector3d& x) { return idealHeadInverse(x, kI); }, h, 1e-7);
		const double scale = 1 + numInv.cwiseAbs().maxCoeff();
		EXPECT_LT((idealHeadInverseJacobian(h, kI) - numInv).cwiseAbs().maxCoeff() / scale, 1e-6);
	}
}

TEST(IdealHead, InverseRoundTrips)
{
	std::mt19937 rng(11);
	for (int k = 0; k < 1000; ++k)
	{
		const Eigen::Vector3d m = randomPoint(rng);
		EXPECT_LT((idealHeadInverse(idealHeadMeasure(m, kI), kI) - m).norm(),
		          1e-9 * (1 + m.norm()));
	}
	EXPECT_THROW(idealHeadInverse({0, 0, 0}, kI), std::invalid_argument);
	EXPECT_THROW(idealHeadInverse({0, 0, -0.1}, kI), std::invalid_argument);
}

TEST(IdealHead, InverseJacobianIsTheInverseOfTheJacobian)
{
	std::mt19937 rng(3);
	for (int k = 0; k < 100; ++k)
	{
		const Eigen::Vector3d m = randomPoint(rng);
		const Eigen::Matrix3d prod =
		    idealHeadJacobian(m, kI) * idealHeadInverseJacobian(idealHeadMeasure(m, kI), kI);
		EXPECT_LT((prod - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff(), 1e-8);
	}
}
