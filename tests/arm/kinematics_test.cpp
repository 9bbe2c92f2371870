// Forward kinematics of the RTX against the printed T06 of thesis B.3.2, against Orocos KDL, and
// the Jacobian against KDL and central differences.
#include "ArmTestUtil.h"

#include <mrolr/arm/GripperPose.h>
#include <mrolr/arm/RtxKdl.h>
#include <mrolr/arm/RtxKinematics.h>

#include <gtest/gtest.h>
#include <kdl/chainfksolverpos_recursive.hpp>
#include <kdl/chainjnttojacsolver.hpp>

#include <mrpt/core/bits_math.h>
#include <mrpt/opengl/CSetOfObjects.h>

#include <cmath>

using namespace mrolr::arm;

namespace
{
RtxJoints anyJoints(std::mt19937& rng)
{
	std::uniform_real_distribution<double> q(-M_PI, M_PI), d(-100, 1000);
	RtxJoints j;
	j.d1_mm = d(rng);
	for (auto& v : j.q_rad) v = q(rng);
	return j;
}
}  // namespace

TEST(ArmKinematics, MatchesPrintedT06Elements)
{
	std::mt19937 rng(1);
	const RtxKinematics kin;
	for (int n = 0; n < 200; ++n)
	{
		const RtxJoints j = anyJoints(rng);
		const Eigen::Matrix4d T = kin.T06(j).matrix();
		const double q1 = j.q(1), q2 = j.q(2), q3 = j.q(3), q4 = j.q(4), q5 = j.q(5), q6 = j.q(6);
		const double S1 = sin(q1), C1 = cos(q1), S2 = sin(q2), C2 = cos(q2), S3 = sin(q3),
		             C3 = cos(q3), S4 = sin(q4), C4 = cos(q4), S5 = sin(q5), C5 = cos(q5),
		             S6 = sin(q6), C6 = cos(q6), S34 = sin(q3 + q4);
		// T06[i,j] of B.3.2 (1-based), copied from the thesis's expressions.
		EXPECT_NEAR(T(0, 2), cos(q1 + q2 + q3 + q4) * S5, 1e-12);
		EXPECT_NEAR(T(1, 2), sin(q1 + q2 + q3 + q4) * S5, 1e-12);
		EXPECT_NEAR(T(2, 2), -C5, 1e-12);
		EXPECT_NEAR(T(2, 0), C6 * S5, 1e-12);
		EXPECT_NEAR(T(2, 1), -(S5 * S6), 1e-12);
		EXPECT_NEAR(T(2, 3), j.d1_mm - 177 * C5, 1e-9);
		const double inner = 254 * C3 + 177 * C3 * C4 * S5 - 177 * S3 * S4 * S5;
		EXPECT_NEAR(T(0, 3),
		            -(S1 * (254 * S2 + S2 * inner + C2 * (254 * S3 + 177 * S34 * S5))) +
		                C1 * (254 * C2 + C2 * inner - S2 * (254 * S3 + 177 * S34 * S5)),
		            1e-9);
		EXPECT_NEAR(T(1, 3),
		            C1 * (254 * S2 + S2 * inner + C2 * (254 * S3 + 177 * S34 * S5)) +
		                S1 * (254 * C2 + C2 * inner - S2 * (254 * S3 + 177 * S34 * S5)),
		            1e-9);
		const double a = -(S3 * (C5 * C6 * S4 - C4 * S6)) + C3 * (C4 * C5 * C6 + S4 * S6);
		const double b = C3 * (C5 * C6 * S4 - C4 * S6) + S3 * (C4 * C5 * C6 + S4 * S6);
		EXPECT_NEAR(T(0, 0), -(S1 * (S2 * a + C2 * b)) + C1 * (C2 * a - S2 * b), 1e-12);
		EXPECT_NEAR(T(1, 0), C1 * (S2 * a + C2 * b) + S1 * (C2 * a - S2 * b), 1e-12);
		EXPECT_NEAR(T(3, 3), 1.0, 0);
	}
}

TEST(ArmKinematics, InitialConfigurationHoldsTheGripperLevelAtColumnHeight)
{
	// B.3.1: d1 = 922, θ2 = θ3 = θ4 = 0, θ5 = 90°, θ6 = 0 → arm stretched along x0, gripper level.
	const Eigen::Isometry3d T = RtxKinematics().T06(RtxJoints());
	EXPECT_NEAR(T.translation().x(), 254 + 254 + 177, 1e-9);
	EXPECT_NEAR(T.translation().y(), 0, 1e-9);
	EXPECT_NEAR(T.translation().z(), 922, 1e-9);
	EXPECT_TRUE(T.linear().col(2).isApprox(Eigen::Vector3d::UnitX(), 1e-12));
}

TEST(ArmKinematics, AgreesWithKdlForwardKinematics)
{
	std::mt19937 rng(2);
	const RtxKinematics kin;
	for (int n = 0; n < 500; ++n)
	{
		const RtxJoints j = anyJoints(rng);
		KDL::Chain chain = rtxKdlChain(kin.options(), j.q(1));
		KDL::ChainFkSolverPos_recursive fk(chain);
		KDL::Frame F;
		ASSERT_GE(fk.JntToCart(toKdl(j), F), 0);
		const Eigen::Isometry3d T = kin.T06(j);
		EXPECT_LT(test::positionError(T, fromKdl(F)), 1e-9);
		EXPECT_LT(test::rotationError(T, fromKdl(F)), 1e-12);
	}
}

TEST(ArmKinematics, JacobianAgreesWithKdlAndCentralDifferences)
{
	std::mt19937 rng(3);
	const RtxKinematics kin;
	for (int n = 0; n < 100; ++n)
	{
		const RtxJoints j = anyJoints(rng);
		const Jacobian6 J = kin.jacobian(j);
		KDL::Chain chain = rtxKdlChain(kin.options(), j.q(1));
		KDL::ChainJntToJacSolver jac(chain);
		KDL::Jacobian Jk(6);
		ASSERT_GE(jac.JntToJac(toKdl(j), Jk), 0);
		EXPECT_LT((J - Jk.data).cwiseAbs().maxCoeff(), 1e-9);
		const double h = 1e-6;
		for (int c = 0; c < 6; ++c)
		{
			RtxJoints jp = j, jm = j;
			Eigen::Matrix<double, 6, 1> v = j.active();
			v[c] += h;
			jp.setActive(v);
			v[c] -= 2 * h;
			jm.setActive(v);
			const Eigen::Vector3d dp =
			    (kin.T06(jp).translation() - kin.T06(jm).translation()) / (2 * h);
			EXPECT_LT((dp - J.block<3, 1>(0, c)).norm(), 1e-5) << "column " << c;
		}
	}
}

TEST(ArmKinematics, YawPitchRollConventionIsTheWristOfTheArm)
{
	// With q1 = 0: yaw = q2 + q3 + q4, pitch = 90° − q5, roll = q6.
	std::mt19937 rng(4);
	const RtxKinematics kin;
	for (int n = 0; n < 200; ++n)
	{
		RtxJoints j = anyJoints(rng);
		j.q_rad[0] = 0;
		const Eigen::Isometry3d T = kin.T06(j);
		const Eigen::Matrix3d R =
		    rotationFromYawPitchRoll(mrpt::RAD2DEG(j.q(2) + j.q(3) + j.q(4)),
		                             90 - mrpt::RAD2DEG(j.q(5)), mrpt::RAD2DEG(j.q(6)));
		EXPECT_LT((R - T.linear()).cwiseAbs().maxCoeff(), 1e-12);
		const Eigen::Isometry3d back = poseFromGripper(gripperFromPose(T));
		EXPECT_LT(test::rotationError(back, T), 1e-9);
	}
	// pitch = 90° approaches straight down; yaw 90° heads along +y.
	EXPECT_TRUE(rotationFromYawPitchRoll(0, 90, 0).col(2).isApprox(-Eigen::Vector3d::UnitZ()));
	EXPECT_TRUE(rotationFromYawPitchRoll(90, 0, 0).col(2).isApprox(Eigen::Vector3d::UnitY()));
}

TEST(ArmKinematics, DrawingChainIsScaledAndDrawable)
{
	const auto chain = RtxKinematics().chain(RtxJoints(), 0.001);
	mrpt::opengl::CSetOfObjects::Ptr gl = mrpt::opengl::CSetOfObjects::Create();
	std::vector<mrpt::poses::CPose3D> poses;
	chain.getAs3DObject(gl, &poses);
	EXPECT_GT(gl->size(), 0u);
	ASSERT_EQ(poses.size(), 7u);
	EXPECT_NEAR(poses.back().x(), 0.685, 1e-12);  // metres
	EXPECT_NEAR(poses.back().z(), 0.922, 1e-12);
}
