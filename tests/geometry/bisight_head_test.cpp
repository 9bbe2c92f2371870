// BiSight head frames, projection and fixation (thesis 4.2.2–4.2.4).
#include <mrolr/geometry/BiSightHead.h>

#include "geometry_test_util.h"
#include "../common/ThrownMessage.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace mrolr::geometry;
using mrolr::geometry::test_util::numericJacobian;

namespace
{
std::string messageOf(const BiSightHead& head, const Eigen::Vector3d& p)
{
	return mrolr::test_support::messageOf<FixationError>([&] { head.fixate(p); }, "no error");
}
}  // namespace

TEST(BiSightHead, OpticCentresAtZeroAnglesAreTheSummedOffsets)
{
	const BiSightHead head(test_util::offsetTestOptions());
	const Eigen::Isometry3d L = head.T_LinC0({}), R = head.T_RinC0({});
	EXPECT_TRUE(L.translation().isApprox(Eigen::Vector3d(0.125, 0.052, 0.031 + 0.067), 1e-15));
	EXPECT_TRUE(R.translation().isApprox(Eigen::Vector3d(-0.125, 0.052, 0.031 + 0.067), 1e-15));
	EXPECT_TRUE(L.linear().isIdentity(1e-15));
	EXPECT_TRUE(R.linear().isIdentity(1e-15));
}

TEST(BiSightHead, JointsTurnTheOpticAxisTheDocumentedWay)
{
	const BiSightHead head(test_util::offsetTestOptions());
	// Positive pan looks left (+x), positive tilt looks up (+y).
	EXPECT_NEAR(head.T_LinC0({0.3, 0, 0, 0}).linear().col(2).x(), std::sin(0.3), 1e-15);
	EXPECT_NEAR(head.T_LinC0({0, 0.2, 0, 0}).linear().col(2).y(), std::sin(0.2), 1e-15);
	// Negative left vergence and positive right vergence converge (axes cross ahead).
	const HeadAngles conv{0, 0, -0.1, 0.1};
	EXPECT_LT(head.T_LinC0(conv).linear().col(2).x(), 0);
	EXPECT_GT(head.T_RinC0(conv).linear().col(2).x(), 0);
}

TEST(BiSightHead, UpInTheLeftCameraIsC0sVertical)
{
	const BiSightHead head(test_util::offsetTestOptions());
	// Pan turns about the vertical: up in L depends on the tilt only, (0, cos e, sin e).
	const Eigen::Vector3d up = head.up_L({0.4, -0.35, 0, 0});
	EXPECT_TRUE(up.isApprox(Eigen::Vector3d(0, std::cos(0.35), -std::sin(0.35)), 1e-12));
	// With vergence: a point raised by h in C0 moves by h · up_L in L.
	const HeadAngles a{-0.2, -0.3, -0.08, 0.08};
	const Eigen::Vector3d p(0.1, -0.4, 0.9), h = 0.25 * Eigen::Vector3d::UnitY();
	const Eigen::Vector3d moved = head.pointInCamera(Side::Left, p + h, a) -
	                              head.pointInCamera(Side::Left, p, a);
	EXPECT_TRUE(moved.isApprox(0.25 * head.up_L(a), 1e-12));
	EXPECT_NEAR(head.up_L(a).norm(), 1.0, 1e-12);
}

TEST(BiSightHead, PointInCameraIsEquation4_22)
{
	const BiSightOptions o = test_util::offsetTestOptions();
	const BiSightHead head(o);
	const Eigen::Vector3d pL(o.interocular_m / 2, 0, o.pan_offset_m), pR(-pL.x(), 0, pL.z());
	const Eigen::Vector3d c(0, o.tilt_offset_m, 0), n(0, 0, o.optic_offset_m);
	std::mt19937 rng(3);
	std::uniform_real_distribution<double> ang(-0.7, 0.7);
	for (int k = 0; k < 50; ++k)
	{
		const HeadAngles a{ang(rng), ang(rng), ang(rng), ang(rng)};
		const Eigen::Vector3d m = test_util::randomPointAhead(rng);
		const Eigen::Matrix3d R21 = R_C2fromC1(a.tilt), R10 = R_C1fromC0(a.pan);
		const Eigen::Vector3d mL = R_LfromC2(a.verg_left) * (R21 * (R10 * m - pL) - c) - n;
		const Eigen::Vector3d mR = R_LfromC2(a.verg_right) * (R21 * (R10 * m - pR) - c) - n;
		EXPECT_TRUE(head.pointInCamera(Side::Left, m, a).isApprox(mL, 1e-13));
		EXPECT_TRUE(head.pointInCamera(Side::Right, m, a).isApprox(mR, 1e-13));
	}
}

TEST(BiSightHead, ComputerVisionPoseFlipsXAndYOnly)
{
	const BiSightHead head(test_util::offsetTestOptions());
	const HeadAngles a{0.2, -0.1, -0.05, 0.07};
	for (Side s : {Side::Left, Side::Right})
	{
		const Eigen::Isometry3d T = head.T_CamInC0(s, a), Tcv = head.T_CamCvInC0(s, a);
		EXPECT_TRUE(Tcv.translation().isApprox(T.translation(), 1e-15));
		EXPECT_TRUE(Tcv.linear().col(0).isApprox(-T.linear().col(0), 1e-15));  // right = −left
		EXPECT_TRUE(Tcv.linear().col(1).isApprox(-T.linear().col(1), 1e-15));  // down = −up
		EXPECT_TRUE(Tcv.linear().col(2).isApprox(T.linear().col(2), 1e-15));
		// The CV camera with K(fx, fy, cx=u0, cy=v0) sees the same pixels as the thesis camera.
		const Eigen::Vector3d p(0.3, 0.1, 2.5), q = Tcv.inverse() * p;
		const StereoPixels px = head.project(p, a);
		const double u = head.camera().focal_px_u * q.x() / q.z() + head.camera().u0_px;
		const double v = head.camera().focal_px_v * q.y() / q.z() + head.camera().v0_px;
		EXPECT_NEAR(u, s == Side::Left ? px.uL : px.uR, 1e-10);
		EXPECT_NEAR(v, s == Side::Left ? px.vL : px.vR, 1e-10);
	}
}

TEST(BiSightHead, ProjectionJacobianMatchesCentralDifferences)
{
	const BiSightHead head(test_util::offsetTestOptions());
	std::mt19937 rng(4);
	for (int k = 0; k < 200; ++k)
	{
		const Eigen::Vector3d m = test_util::randomPointAhead(rng);
		const HeadAngles a = test_util::randomAnglesLookingNear(head, m, rng);
		Eigen::Matrix<double, 4, 3> J;
		head.project(m, a, &J);
		const auto f = [&](const Eigen::Vector3d& x) { return head.project(x, a).asVector(); };
		const auto num = numericJacobian<4, 3>(f, m, 1e-6);
		EXPECT_LT((J - num).cwiseAbs().maxCoeff(), 1e-5 * (1 + num.cwiseAbs().maxCoeff()));
	}
}

TEST(BiSightHead, ProjectionRejectsPointsBehindACamera)
{
	const BiSightHead head(test_util::offsetTestOptions());
	EXPECT_THROW(head.project({0, 0, -1}, {}), ProjectionError);
	try
	{
		// Between the optic centres' planes: in front of C0 but behind both optic centres.
		head.project({0, 0, 0.05}, {});
		FAIL() << "expected ProjectionError";
	}
	catch (const ProjectionError& e)
	{
		EXPECT_NE(std::string(e.what()).find("left camera"), std::string::npos) << e.what();
	}
}

TEST(BiSightHead, FixationPutsThePointOnBothPrincipalPoints)
{
	const BiSightHead head(test_util::offsetTestOptions());
	const Eigen::Vector4d pp(318.5, 244.25, 318.5, 244.25);
	std::mt19937 rng(5);
	for (int k = 0; k < 500; ++k)
	{
		const Eigen::Vector3d m = test_util::randomPointAhead(rng);
		const HeadAngles a = head.fixate(m);
		EXPECT_LT((head.project(m, a).asVector() - pp).cwiseAbs().maxCoeff(), 1e-6)
		    << m.transpose();
		EXPECT_EQ(a.verg_right, -a.verg_left);  // eq 4.33
		EXPECT_LT(a.verg_left, 0);
	}
}

TEST(BiSightHead, FixationAnglesHaveTheirClosedFormsWithoutOffsets)
{
	BiSightOptions o = test_util::offsetTestOptions();
	o.pan_offset_m = o.tilt_offset_m = o.optic_offset_m = 0;
	const BiSightHead head(o);
	const Eigen::Vector3d m(0.4, 0.3, 1.2);
	const HeadAngles a = head.fixate(m);
	EXPECT_NEAR(a.pan, std::atan2(0.4, 1.2), 1e-14);  // eq 4.27
	const double horiz = std::hypot(0.4, 1.2);
	EXPECT_NEAR(a.tilt, std::atan2(0.3, horiz), 1e-14);             // eq 4.30 with p = c = 0
	EXPECT_NEAR(a.verg_left, -std::atan2(0.125, m.norm()), 1e-14);  // eq 4.32 with n = 0
}

TEST(BiSightHead, UnfixatablePointsGiveAClearError)
{
	const BiSightHead head(test_util::offsetTestOptions());
	EXPECT_NE(messageOf(head, {0, 1, 0}).find("pan axis"), std::string::npos);
	EXPECT_NE(messageOf(head, {0.2, 0, -2}).find("behind the head"), std::string::npos);
	EXPECT_NE(messageOf(head, {0, 3, 1}).find("tilt"), std::string::npos);
	EXPECT_NE(messageOf(head, {0, 0.03, 0.04}).find("tilt axis"), std::string::npos);
	EXPECT_NE(messageOf(head, {0, 0.05, 0.15}).find("vergence"), std::string::npos);
	EXPECT_EQ(messageOf(head, {0, 0, 2}), "no error");
	BiSightOptions narrow = test_util::offsetTestOptions();
	narrow.pan_limit_deg = 60;
	EXPECT_NE(messageOf(BiSightHead(narrow), {3, 0, 1}).find("pan 71.5"), std::string::npos);
}

TEST(BiSightHead, TwoPixelFixationErrorIsAbout0_0024Rad)
{
	// Thesis 5.3.1: δε ≈ δv / (f k_v) = 2 / 807 ≈ 0.0024 rad for f·k_v = 807 px.
	const BiSightHead head(test_util::offsetTestOptions());
	const Eigen::Vector3d ray0 = head.camera().backProject({318.5, 244.25});
	const Eigen::Vector3d ray2 = head.camera().backProject({318.5, 244.25 + 2});
	const double angle = std::acos(ray0.normalized().dot(ray2.normalized()));
	EXPECT_NEAR(angle, 0.0024, 0.0001);
	// The same through the head: tilting a fixated head by that angle moves the image by ~2 px.
	const Eigen::Vector3d m(0.2, 0.4, 4);
	HeadAngles a = head.fixate(m);
	a.tilt += angle;
	EXPECT_NEAR(head.project(m, a).vL - 244.25, 2.0, 0.05);
}
