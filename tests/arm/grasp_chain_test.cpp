// The grasp chain of thesis 6.6–6.7: the printed transforms of both mountings, calibration
// (eq 6.7.2), the grasp line carried into the arm frame, and the head model's left camera → C0.
#include "ArmTestUtil.h"

#include <mrolr/arm/GraspChain.h>
#include <mrolr/arm/GripperPose.h>
#include <mrolr/arm/HeadToArm.h>
#include <mrolr/arm/PoseText.h>
#include <mrolr/util/Config.h>

#include <mrpt/config/CConfigFileMemory.h>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

using namespace mrolr::arm;
using ::testing::HasSubstr;

namespace
{
Eigen::Isometry3d pose(const std::vector<double>& v)
{
	return poseFrom12(v, "test");
}
}  // namespace

TEST(ArmGraspChain, ThesisParallelMountingMapsTheObjectAsPrinted)
{
	const ArmMount m = ArmMount::fromFile(MROLR_SOURCE_DIR "/config/arm_mount_parallel.ini");
	EXPECT_TRUE(m.T_C0inA.isApprox(pose({0, 0, 1, -627, 1, 0, 0, -1040, 0, 1, 0, 711}), 1e-12));
	// The object at (470, −441, 847) in C0 (the OCR's "47.0"; only 470 gives the printed result).
	const Eigen::Isometry3d T_OinC0 = pose({0, 1, 0, 470, 0, 0, -1, -441, -1, 0, 0, 847});
	const Eigen::Isometry3d T_OinA = objectInArm(m.T_C0inA, T_OinC0);
	const Eigen::Isometry3d printed = pose({-1, 0, 0, 220, 0, 1, 0, -570, 0, 0, -1, 270});
	EXPECT_LT((T_OinA.matrix() - printed.matrix()).cwiseAbs().maxCoeff(), 1e-12);
}

TEST(ArmGraspChain, ThesisFortyFiveDegreeCalibrationGivesTheComputedTranslation)
{
	const Eigen::Isometry3d T_OinA = parsePose12("-.707,0,.707,545, .707,0,.707,0, 0,1,0,429", "A");
	const Eigen::Isometry3d T_OinC0 = pose({1, 0, 0, 747, 0, 1, 0, -246, 0, 0, 1, 1003.3});
	const Eigen::Isometry3d T_C0inA = calibrateHeadInArm(T_OinA, T_OinC0);
	const Eigen::Isometry3d T_AinC0 = T_C0inA.inverse(Eigen::Isometry);
	// Printed (460, −675, 618); the thesis's own inputs give x = 1132.4, as the issue notes.
	EXPECT_NEAR(T_AinC0.translation().x(), 1132.37, 0.01);
	EXPECT_NEAR(T_AinC0.translation().y(), -675.0, 1e-9);
	EXPECT_NEAR(T_AinC0.translation().z(), 617.93, 0.01);
	// Its rotation is the one the thesis wants for the 45° mounting.
	const Eigen::Isometry3d printed_R = parsePose12("-.707,.707,0,0, 0,0,1,0, .707,.707,0,0", "R");
	EXPECT_LT((T_AinC0.linear() - printed_R.linear()).cwiseAbs().maxCoeff(), 1e-12);
	// The shipped mounting file holds this T_C0inA and maps the test object back onto T_OinA.
	const ArmMount m = ArmMount::fromFile(MROLR_SOURCE_DIR "/config/arm_mount_45.ini");
	EXPECT_LT((m.T_C0inA.matrix() - T_C0inA.matrix()).cwiseAbs().maxCoeff(), 1e-3);
	EXPECT_LT(test::positionError(objectInArm(m.T_C0inA, T_OinC0), T_OinA), 1e-3);
}

TEST(ArmGraspChain, CalibrationFromSeveralNoisyObjectsRecoversTheMounting)
{
	std::mt19937 rng(11);
	std::normal_distribution<double> noise(0, 1.0);  // mm
	const ArmMount m = ArmMount::fromFile(MROLR_SOURCE_DIR "/config/arm_mount_45.ini");
	std::vector<std::pair<Eigen::Isometry3d, Eigen::Isometry3d>> pairs;
	for (int k = 0; k < 20; ++k)
	{
		Eigen::Isometry3d T_OinC0 = Eigen::Isometry3d::Identity();
		T_OinC0.linear() = Eigen::Quaterniond::UnitRandom().toRotationMatrix();
		T_OinC0.translation() = Eigen::Vector3d(600 + 20 * k, -200, 900);
		Eigen::Isometry3d T_OinA = m.T_C0inA * T_OinC0;
		T_OinA.translation() += Eigen::Vector3d(noise(rng), noise(rng), noise(rng));
		pairs.emplace_back(T_OinA, T_OinC0);
	}
	const Eigen::Isometry3d est = calibrateHeadInArm(pairs);
	EXPECT_LT(test::positionError(est, m.T_C0inA), 1.5);
	EXPECT_LT(test::rotationError(est, m.T_C0inA), 1e-9);  // rotations were noise-free
	EXPECT_THROW(calibrateHeadInArm({}), std::invalid_argument);
}

TEST(ArmGraspChain, GraspLineIsCarriedWithTheObject)
{
	mrolr::model::Grasp g;
	g.p_mm = {10, 20, 30};
	g.yaw_deg = 0;
	g.pitch_deg = 90;
	g.roll_deg = 180;  // approach along −z_O with x_G = x_O: the thesis's object frame itself
	const Eigen::Isometry3d T_GinO = graspInObject(g);
	EXPECT_TRUE(T_GinO.linear().isApprox(
	    pose({-1, 0, 0, 0, 0, 1, 0, 0, 0, 0, -1, 0}).linear().transpose() *
	    pose({-1, 0, 0, 0, 0, 1, 0, 0, 0, 0, -1, 0}).linear() * T_GinO.linear()));
	EXPECT_TRUE(T_GinO.linear().col(2).isApprox(-Eigen::Vector3d::UnitZ(), 1e-12));
	const Eigen::Isometry3d T_C0inA = pose({0, 0, 1, -627, 1, 0, 0, -1040, 0, 1, 0, 711});
	const Eigen::Isometry3d T_OinC0 = pose({0, 1, 0, 470, 0, 0, -1, -441, -1, 0, 0, 847});
	const Eigen::Isometry3d T_GinA = graspInArm(T_C0inA, T_OinC0, g);
	// The grasp point is the model point moved by T_OinA (6.6: multiply the grasp vector).
	EXPECT_LT((T_GinA.translation() - (T_C0inA * T_OinC0) * g.p_mm).norm(), 1e-9);
	EXPECT_LT(test::rotationError(T_GinA, T_C0inA * T_OinC0 * T_GinO), 1e-12);
}

TEST(ArmGraspChain, MountingFileErrorsNameTheKey)
{
	mrpt::config::CConfigFileMemory few("[arm_mount]\nT_C0inA = 1 0 0 0 1 0\n");
	ArmMount m;
	EXPECT_THAT([&] { m.loadFromConfigFile(few, "arm_mount"); },
	            ::testing::ThrowsMessage<mrolr::util::ConfigError>(HasSubstr("T_C0inA")));
	mrpt::config::CConfigFileMemory skew("[arm_mount]\nT_C0inA = 1 1 0 0 0 1 0 0 0 0 1 0\n");
	EXPECT_THAT([&] { m.loadFromConfigFile(skew, "arm_mount"); },
	            ::testing::ThrowsMessage<mrolr::util::ConfigError>(HasSubstr("not a rotation")));
	EXPECT_THROW(ArmMount::fromFile("/nonexistent.ini"), mrolr::util::ConfigError);
}

TEST(ArmGraspChain, LeftCameraPoseIsMovedToTheHeadCentre)
{
	const mrolr::geometry::BiSightHead head;
	mrolr::geometry::HeadAngles a;
	a.pan = 0.2;
	a.tilt = -0.1;
	a.verg_left = -0.05;
	a.verg_right = 0.05;
	Eigen::Isometry3d T_OinL = Eigen::Isometry3d::Identity();
	T_OinL.translation() = Eigen::Vector3d(30, -20, 800);  // mm in front of the left camera
	const Eigen::Isometry3d T_OinC0 = objectInHeadCentre(head, a, T_OinL);
	// The head maps the same point (in metres) with its own camera model.
	const Eigen::Vector3d p_L_m =
	    head.pointInCamera(mrolr::geometry::Side::Left, T_OinC0.translation() / 1000.0, a);
	EXPECT_LT((p_L_m * 1000.0 - T_OinL.translation()).norm(), 1e-9);
}
