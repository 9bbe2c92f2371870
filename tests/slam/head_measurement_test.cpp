#include <mrolr/slam/HeadMeasurement.h>

#include "slam_test_util.h"

#include <gtest/gtest.h>

#include <random>

using namespace mrolr::slam;

namespace
{
const HeadConstants kHead{0.25, 1.0};
}

TEST(HeadMeasurement, PointInHeadHasItsGeometricMeaning)
{
	// Vehicle at z = 1, x = 2 facing +x (φ = 90°): a point 3 m further along +x, at head height, is
	// straight ahead; a point at larger z is to the vehicle's right (negative m_x).
	const Eigen::Vector3d xv(1, 2, M_PI / 2);
	const auto m = pointInHead(xv, {5, 1, 1}, kHead);
	EXPECT_NEAR((m - Eigen::Vector3d(0, 0, 3)).norm(), 0, 1e-12);
	EXPECT_LT(pointInHead(xv, {2, 1, 3}, kHead).x(), 0);
	const auto h = predictMeasurement(xv, {5, 2, 1}, kHead);
	EXPECT_NEAR(h[0], 0, 1e-12);
	EXPECT_NEAR(h[1], std::atan2(1.0, 3.0), 1e-12);
}

TEST(HeadMeasurement, JacobiansMatchCentralDifferences)
{
	std::mt19937 rng(5);
	std::uniform_real_distribution<double> u(-3, 3), a(-M_PI, M_PI);
	for (int k = 0; k < 200; ++k)
	{
		const Eigen::Vector3d xv(u(rng), u(rng), a(rng));
		Eigen::Vector3d y(u(rng), 1 + u(rng) / 2, u(rng));
		if ((y - headCentreInW(xv, kHead)).norm() < 0.5) continue;
		const auto J = measurementJacobians(xv, y, kHead);
		const auto hx = [&](const Eigen::Vector3d& v)
		{ return Eigen::Vector3d(predictMeasurement(v, y, kHead)); };
		const auto hy = [&](const Eigen::Vector3d& p)
		{ return Eigen::Vector3d(predictMeasurement(xv, p, kHead)); };
		EXPECT_LT((J.H_xv - slamtest::centralDiff(hx, xv)).cwiseAbs().maxCoeff(), 1e-7);
		EXPECT_LT((J.H_y - slamtest::centralDiff(hy, y)).cwiseAbs().maxCoeff(), 1e-7);
		// Initialisation (eq 5.46) inverts the measurement, with matching Jacobians.
		const Eigen::Vector3d h = predictMeasurement(xv, y, kHead);
		const auto g = initialiseFromMeasurement(xv, h, kHead);
		EXPECT_LT((g.p_FinW - y).norm(), 1e-9);
		const auto gx = [&](const Eigen::Vector3d& v)
		{ return Eigen::Vector3d(initialiseFromMeasurement(v, h, kHead).p_FinW); };
		const auto gh = [&](const Eigen::Vector3d& hh)
		{ return Eigen::Vector3d(initialiseFromMeasurement(xv, hh, kHead).p_FinW); };
		EXPECT_LT((g.dy_dxv - slamtest::centralDiff(gx, xv)).cwiseAbs().maxCoeff(), 1e-6);
		const double scale = 1 + g.dy_dh.cwiseAbs().maxCoeff();
		EXPECT_LT((g.dy_dh - slamtest::centralDiff(gh, h, 1e-8)).cwiseAbs().maxCoeff() / scale,
		          1e-5);
	}
}

TEST(HeadMeasurement, DifferenceWrapsAngles)
{
	const Eigen::Vector3d d = measurementDifference({M_PI - 0.01, 0, 0.1}, {-M_PI + 0.01, 0, 0.1});
	EXPECT_NEAR(d[0], -0.02, 1e-12);
}
