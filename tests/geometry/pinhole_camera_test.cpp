#include <mrolr/geometry/PinholeCamera.h>

#include "geometry_test_util.h"

#include <gtest/gtest.h>

using namespace mrolr::geometry;
using mrolr::geometry::test_util::numericJacobian;

namespace
{
PinholeCamera skewedCamera()
{
	PinholeCamera c;
	c.focal_px_u = 800;
	c.focal_px_v = 812;
	c.u0_px = 317.5;
	c.v0_px = 243.25;
	return c;
}
}  // namespace

TEST(PinholeCamera, ThesisAxesMapLeftAndUpToSmallerPixels)
{
	const PinholeCamera c = skewedCamera();
	// On the optic axis: the principal point (eq 4.2).
	EXPECT_TRUE(c.project({0, 0, 3}).isApprox(Eigen::Vector2d(317.5, 243.25)));
	// x left, y up: a point up and to the left appears up (v smaller) and left (u smaller).
	const Eigen::Vector2d uv = c.project({0.1, 0.2, 2});
	EXPECT_NEAR(uv.x(), 317.5 - 800 * 0.05, 1e-12);
	EXPECT_NEAR(uv.y(), 243.25 - 812 * 0.1, 1e-12);
	EXPECT_THROW(c.project({0, 0, 0}), ProjectionError);
	EXPECT_THROW(c.project({0.1, 0, -1}), ProjectionError);
}

TEST(PinholeCamera, JacobianMatchesCentralDifferences)
{
	const PinholeCamera c = skewedCamera();
	std::mt19937 rng(1);
	for (int k = 0; k < 100; ++k)
	{
		const Eigen::Vector3d m = test_util::randomPointAhead(rng);
		Eigen::Matrix<double, 2, 3> J;
		c.project(m, &J);
		const auto num =
		    numericJacobian<2, 3>([&](const Eigen::Vector3d& x) { return c.project(x); }, m, 1e-6);
		EXPECT_LT((J - num).cwiseAbs().maxCoeff(), 1e-5) << m.transpose();
	}
}

TEST(PinholeCamera, BackProjectionIsTheRayOfThePixel)
{
	const PinholeCamera c = skewedCamera();
	const Eigen::Vector2d uv(12.5, 401);
	const Eigen::Vector3d ray = c.backProject(uv);
	for (double depth : {0.5, 2.0, 30.0}) EXPECT_TRUE(c.project(depth * ray).isApprox(uv, 1e-12));
	// eq 4.6: m ∝ C⁻¹ (u, v, 1); eq 4.5: (u, v, 1) ∝ C m.
	const Eigen::Vector3d h = c.inverseCalibrationMatrix() * uv.homogeneous();
	EXPECT_TRUE((h / h.z()).isApprox(ray, 1e-14));
	const Eigen::Vector3d Cm = c.calibrationMatrix() * Eigen::Vector3d(0.3, -0.2, 1.7);
	EXPECT_TRUE((Cm / Cm.z()).head<2>().isApprox(c.project({0.3, -0.2, 1.7}), 1e-12));
	EXPECT_TRUE((c.calibrationMatrix() * c.inverseCalibrationMatrix()).isIdentity(1e-14));
	const auto num =
	    numericJacobian<3, 2>([&](const Eigen::Vector2d& x) { return c.backProject(x); }, uv, 1e-3);
	EXPECT_TRUE(c.backProjectJacobian().isApprox(num, 1e-9));
}

TEST(PinholeCamera, TCameraGivesTheSamePixelsInTheComputerVisionAxes)
{
	const PinholeCamera c = skewedCamera();
	const mrpt::img::TCamera cam = c.toTCamera();
	EXPECT_EQ(cam.ncols, 640u);
	EXPECT_EQ(cam.nrows, 480u);
	const Eigen::Matrix3d K = cam.intrinsicParams.asEigen();
	std::mt19937 rng(2);
	for (int k = 0; k < 20; ++k)
	{
		const Eigen::Vector3d m = test_util::randomPointAhead(rng);
		const Eigen::Vector3d m_cv(-m.x(), -m.y(), m.z());  // x right, y down
		const Eigen::Vector3d h = K * m_cv;
		EXPECT_TRUE((h / h.z()).head<2>().isApprox(c.project(m), 1e-12));
	}
	const PinholeCamera back = PinholeCamera::fromTCamera(cam);
	EXPECT_EQ(back.focal_px_u, c.focal_px_u);
	EXPECT_EQ(back.focal_px_v, c.focal_px_v);
	EXPECT_EQ(back.u0_px, c.u0_px);
	EXPECT_EQ(back.v0_px, c.v0_px);
	EXPECT_EQ(back.width_px, 640);
	mrpt::img::TCamera distorted = cam;
	distorted.dist[0] = -0.2;
	EXPECT_THROW(PinholeCamera::fromTCamera(distorted), GeometryError);
}

TEST(PinholeCamera, ImageBounds)
{
	const PinholeCamera c;
	EXPECT_TRUE(c.isInImage({0, 0}));
	EXPECT_TRUE(c.isInImage({639.9, 479.9}));
	EXPECT_FALSE(c.isInImage({640, 10}));
	EXPECT_FALSE(c.isInImage({10, -0.1}));
}
