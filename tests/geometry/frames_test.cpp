// Thesis frames ↔ MRPT frames (Frames.h): axes, round trips and consistency with MRPT's algebra.
#include <mrolr/geometry/BiSightHead.h>
#include <mrolr/geometry/Frames.h>

#include <mrpt/math/TPose3D.h>
#include <mrpt/poses/CPoint3D.h>

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <random>

using namespace mrolr::geometry;

namespace
{
Eigen::Isometry3d randomPose(std::mt19937& rng)
{
	std::uniform_real_distribution<double> d(-2, 2);
	Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
	T.linear() = Eigen::Quaterniond(Eigen::Vector4d(d(rng), d(rng), d(rng), d(rng)).normalized())
	                 .toRotationMatrix();
	T.translation() << d(rng), d(rng), d(rng);
	return T;
}

Eigen::Vector3d toEigen(const mrpt::math::TPoint3D& p)
{
	return {p.x, p.y, p.z};
}
}  // namespace

TEST(Frames, AxesMapForwardLeftUp)
{
	EXPECT_EQ(toEigen(pointToMrpt({0, 0, 1})), Eigen::Vector3d(1, 0, 0));  // forward
	EXPECT_EQ(toEigen(pointToMrpt({1, 0, 0})), Eigen::Vector3d(0, 1, 0));  // left
	EXPECT_EQ(toEigen(pointToMrpt({0, 1, 0})), Eigen::Vector3d(0, 0, 1));  // up
	EXPECT_NEAR(R_mrptFromThesis().determinant(), 1, 1e-15);
	EXPECT_EQ(pointFromMrpt(pointToMrpt({0.1, -2, 3.5})), Eigen::Vector3d(0.1, -2, 3.5));
}

TEST(Frames, PosesRoundTripAndActOnPointsLikeMrpt)
{
	std::mt19937 rng(11);
	for (int k = 0; k < 50; ++k)
	{
		const Eigen::Isometry3d T = randomPose(rng);
		const mrpt::poses::CPose3D P = poseToMrpt(T);
		EXPECT_TRUE(poseFromMrpt(P).isApprox(T, 1e-12));
		const Eigen::Vector3d p(0.3, -0.7, 2.1);
		const mrpt::math::TPoint3D q = P.composePoint(pointToMrpt(p));
		EXPECT_TRUE(pointFromMrpt(q).isApprox(T * p, 1e-12));
		EXPECT_TRUE(cameraPoseFromMrpt(cameraPoseToMrpt(T)).isApprox(T, 1e-12));
	}
}

TEST(Frames, VehicleStateIsCPose2D)
{
	const Eigen::Vector3d xv(2.0, -0.5, 0.4);  // z forward, x left, φ from z towards x
	const mrpt::poses::CPose2D pose = vehicleToMrpt(xv);
	EXPECT_EQ(pose.x(), 2.0);
	EXPECT_EQ(pose.y(), -0.5);
	EXPECT_NEAR(pose.phi(), 0.4, 1e-15);
	EXPECT_TRUE(vehicleFromMrpt(pose).isApprox(xv, 1e-15));
	EXPECT_NEAR(vehicleFromMrpt(mrpt::poses::CPose2D(0, 0, 3 * M_PI / 2))[2], -M_PI / 2, 1e-12);
	// T_C0inW agrees with MRPT's 2-D composition: a point 1 m ahead and 0.2 m left of the head.
	const Eigen::Vector3d ahead(0.2, 0, 1.0);
	const Eigen::Vector3d inW = T_C0inW(xv, 1.1) * ahead;
	const mrpt::math::TPoint3D m = mrpt::poses::CPose3D(pose).composePoint(pointToMrpt(ahead));
	EXPECT_TRUE(pointFromMrpt(m).isApprox(inW - Eigen::Vector3d(0, 1.1, 0), 1e-12));
}

TEST(Frames, ForwardCameraMatchesMrptsCameraConvention)
{
	// MRPT's forward-looking camera on a robot: yaw −90°, pitch 0, roll −90° (x right, y down).
	const mrpt::poses::CPose3D mrptCamera(0, 0, 0, -M_PI / 2, 0, -M_PI / 2);
	const BiSightHead head;
	const mrpt::poses::CPose3D left = cameraPoseToMrpt(head.T_CamCvInC0(Side::Left, {}));
	EXPECT_TRUE(left.getRotationMatrix().asEigen().isApprox(
	    mrptCamera.getRotationMatrix().asEigen(), 1e-12));
	// The left camera is on the robot's left (+y in MRPT) and above C0 by the tilt offset c.
	EXPECT_NEAR(left.y(), head.options().interocular_m / 2, 1e-15);
	EXPECT_NEAR(left.z(), head.options().tilt_offset_m, 1e-15);
}
