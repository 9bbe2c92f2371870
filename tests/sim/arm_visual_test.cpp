// The arm in the rendered pairs: where the RTX stands between the head and the scene, the pair sees
// it (the occlusion is there), its ArUco calibration marker is found where the arm's chain puts it,
// and without draw_arm the same view is the bare scene.
#include <mrolr/arm/AnalyticIk.h>
#include <mrolr/arm/RtxKinematics.h>
#include <mrolr/sim/Lab.h>
#include <mrolr/stereo/ArucoMarker.h>

#include <mrolr/util/Config.h>
#include <gtest/gtest.h>
#include <mrpt/config/CConfigFileMemory.h>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>

#include <fstream>
#include <cmath>
#include <sstream>

using namespace mrolr;

namespace
{
sim::LabOptions labOptions(bool draw_arm)
{
	mrpt::config::CConfigFileMemory cfg(
	    util::openConfigFile(std::string(MROLR_SOURCE_DIR) + "/config/mission_sim.ini").getContent());
	cfg.write("sim_arm", "draw_arm", draw_arm ? "true" : "false");
	return sim::LabOptions::load(cfg, std::string(MROLR_SOURCE_DIR) + "/config");
}

/** The gripper at @p p_GinA_mm pointing up (z_G = z_A), its marker's face (+x_G) turned towards
 * the head as nearly as the wrist allows. */
hw::ArmJoints presenting(const sim::LabOptions& o, const Eigen::Vector3d& p_GinA_mm)
{
	const Eigen::Vector3d to_head = o.mount.T_C0inA.translation() - p_GinA_mm;
	const double facing_deg = std::atan2(to_head.y(), to_head.x()) * 180 / M_PI;
	for (int k = 0; k < 24; ++k)
	{
		const double roll_deg = facing_deg + (k % 2 ? 1 : -1) * 15 * ((k + 1) / 2);
		Eigen::Isometry3d T_GinA = Eigen::Isometry3d::Identity();
		T_GinA.linear() =
		    Eigen::AngleAxisd(roll_deg * M_PI / 180, Eigen::Vector3d::UnitZ()).toRotationMatrix();
		T_GinA.translation() = p_GinA_mm;
		const auto ik = arm::AnalyticIk(o.rtx).solve(T_GinA);
		if (!ik.solutions.empty()) return ik.solutions.front().joints.toMmDeg();
	}
	ADD_FAILURE() << "no IK solution for the presenting pose at any roll";
	return {};
}

struct View
{
	cv::Mat left, right;
};

View presentAndGrab(bool draw_arm, bool decouple_before_grab = false)
{
	const auto o = labOptions(draw_arm);
	sim::Lab lab(o);
	const auto j = presenting(o, {350, 100, 940});
	lab.arm().dock(true);
	lab.arm().moveTo(j);
	if (decouple_before_grab) lab.arm().dock(false);
	const auto T_GinA = arm::RtxKinematics(o.rtx).T06(arm::RtxJoints::fromMmDeg(j));
	const Eigen::Vector3d p_MinC0_mm = lab.trueMount().inverse() * (T_GinA * o.marker.p_MinG_mm);
	const geometry::BiSightHead head(o.bisight);
	lab.head().moveTo(head.fixate(p_MinC0_mm / 1000.0));
	const auto pair = lab.head().grab();
	return {pair.left.asCvMat<cv::Mat>(mrpt::img::DEEP_COPY),
	        pair.right.asCvMat<cv::Mat>(mrpt::img::DEEP_COPY)};
}

/** Pixels of @p a and @p b differing by more than 25 grey levels. */
int changed(const cv::Mat& a, const cv::Mat& b)
{
	cv::Mat d;
	cv::absdiff(a, b, d);
	return cv::countNonZero(d > 25);
}
}  // namespace

TEST(ArmVisual, TheArmBetweenHeadAndSceneOccludesItAndItsMarkerIsWhereTheChainPutsIt)
{
	const View with = presentAndGrab(true), without = presentAndGrab(false);
	if (const char* dir = std::getenv("MROLR_TEST_IMAGES"))
	{
		cv::imwrite(std::string(dir) + "/arm_left.png", with.left);
		cv::imwrite(std::string(dir) + "/arm_right.png", with.right);
		cv::imwrite(std::string(dir) + "/noarm_left.png", without.left);
	}
	// the column, the links and the hand hide a large part of the scene, in both images
	const int area = with.left.rows * with.left.cols;
	EXPECT_GT(changed(with.left, without.left), area / 20);
	EXPECT_GT(changed(with.right, without.right), area / 20);
	// the fixated marker's centre is on both principal points (320, 240), within a pixel or two
	const auto labOpt = labOptions(true);
	for (const cv::Mat* img : {&with.left, &with.right})
	{
		const auto m = stereo::findArucoMarker(*img, labOpt.marker.aruco_id);
		ASSERT_TRUE(m) << "marker not found";
		EXPECT_NEAR(m->centre_px.x(), 320, 2.0);
		EXPECT_NEAR(m->centre_px.y(), 240, 2.0);
	}
	// and it is nowhere in the bare scene
	EXPECT_FALSE(stereo::findArucoMarker(without.left, labOpt.marker.aruco_id));
}

TEST(ArmVisual, ADecoupledArmIsNotInTheView)
{
	const View decoupled = presentAndGrab(true, true), without = presentAndGrab(false);
	const int area = decoupled.left.rows * decoupled.left.cols;
	EXPECT_LT(changed(decoupled.left, without.left), area / 1000);
	EXPECT_LT(changed(decoupled.right, without.right), area / 1000);
}

TEST(ArucoMarker, TheDiagonalsOfASquareCrossAtItsCentre)
{
	// a projected square: the corners of a trapezoid; the crossing lies on both diagonals
	const std::array<Eigen::Vector2d, 4> c{Eigen::Vector2d(0, 0), Eigen::Vector2d(10, 0),
	                                       Eigen::Vector2d(8, 6), Eigen::Vector2d(2, 6)};
	const Eigen::Vector2d x = stereo::diagonalCrossing(c);
	auto cross = [](const Eigen::Vector2d& a, const Eigen::Vector2d& b)
	{ return a.x() * b.y() - a.y() * b.x(); };
	EXPECT_NEAR(cross(c[2] - c[0], x - c[0]), 0, 1e-9);
	EXPECT_NEAR(cross(c[3] - c[1], x - c[1]), 0, 1e-9);
	EXPECT_NEAR(x.x(), 5, 1e-9);  // symmetric about x = 5
}
