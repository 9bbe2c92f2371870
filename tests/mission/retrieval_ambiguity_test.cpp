// An ambiguous pose: the retrieval keeps its grasp only when that grasp grips every rival pose
// the same way: the cube turned by a quarter turn (its grasp may turn in 90° steps), the drink
// package turned round (the jaws grip it from either side); not a cube turned by 45° or moved
// 30 mm.
#include <mrolr/mission/Retrieval.h>
#include <mrolr/model/WireFrameIO.h>
#include "MissionTestConfig.h"

#include <gtest/gtest.h>

using namespace mrolr;

namespace
{
/** Upright 0.7 m ahead of C0 and 0.3 m to its right, on a table 0.75 m high (mm). */
Eigen::Isometry3d onTheTable(const mission::MissionOptions& o, double yaw_deg)
{
	Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
	T.linear().col(0) = Eigen::Vector3d::UnitZ();
	T.linear().col(1) = Eigen::Vector3d::UnitX();
	T.linear().col(2) = Eigen::Vector3d::UnitY();
	T.linear() = Eigen::AngleAxisd(yaw_deg * M_PI / 180, Eigen::Vector3d::UnitY()) * T.linear();
	T.translation() = 1000.0 * Eigen::Vector3d(-0.3, 0.75 - o.bisight.head_height_m, 0.7);
	return T;
}

Eigen::Isometry3d turnedAboutItsAxis(const Eigen::Isometry3d& T_OinC0, double deg)
{
	return T_OinC0 * Eigen::AngleAxisd(deg * M_PI / 180, Eigen::Vector3d::UnitZ());
}
}  // namespace

TEST(RetrievalAmbiguity, AGraspIsKeptOnlyWhenItGripsEveryRivalPoseAlike)
{
	auto cfg = mission::test::defaultMissionConfig();
	const auto o = mission::test::optionsFrom(cfg);
	ASSERT_EQ(o.retrieval.grasp_yaw_search_deg, 90.0);  // the shipped yaw search
	for (const char* name : {"alphabet_cube", "drink_package"})
	{
		SCOPED_TRACE(name);
		const auto wf = model::loadWireFrame(o.models_dir + "/" + name + ".wf");
		const mission::Retrieval retrieval(o, wf);
		const Eigen::Isometry3d P = onTheTable(o, 10);
		const Eigen::Isometry3d T_GinA = retrieval.graspAt(P, 0);
		EXPECT_EQ(retrieval.posesGrippedAlike(T_GinA, 0, {P, turnedAboutItsAxis(P, 180)}), 2);
		EXPECT_EQ(retrieval.posesGrippedAlike(T_GinA, 0, {P, turnedAboutItsAxis(P, 45)}), 1);
		Eigen::Isometry3d moved = P;
		moved.translation().x() += 30;
		EXPECT_EQ(retrieval.posesGrippedAlike(T_GinA, 0, {P, moved}), 1);
	}
	// a quarter turn grips the cube alike (its grasp turns in the yaw search's 90° steps)
	const auto cube = model::loadWireFrame(o.models_dir + "/alphabet_cube.wf");
	const mission::Retrieval retrieval(o, cube);
	const Eigen::Isometry3d P = onTheTable(o, 0);
	EXPECT_EQ(retrieval.posesGrippedAlike(retrieval.graspAt(P, 0), 0, {turnedAboutItsAxis(P, 90)}), 1);
	// without the yaw search only the same pose or the jaws turned round count
	auto fixed = o;
	fixed.retrieval.grasp_yaw_search_deg = 0;
	const mission::Retrieval strict(fixed, cube);
	EXPECT_EQ(strict.posesGrippedAlike(strict.graspAt(P, 0), 0, {turnedAboutItsAxis(P, 90)}), 0);
}
