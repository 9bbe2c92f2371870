// Retrieval missions on the lab with fixed seeds: an object the arm cannot reach from the search
// station is retrieved from a docking pose the robot plans and drives to, and when no docking pose
// reaches, the failure says so and the arm never moves; a docking pose where the base could not
// turn for the room's walls is never driven to.
#include "MissionTestConfig.h"

#include <gtest/gtest.h>

using namespace mrolr;

TEST(RetrievalMission, TheDrinkPackageInTheBackRowIsRetrievedFromTheTablesFarSide)
{
	auto cfg = mission::test::defaultMissionConfig();
	cfg.write("mission", "target", "drink_package");
	cfg.write("mission", "seed", "2");
	const auto run = mission::test::runMission(cfg);
	const auto& d = run.r.docking;
	ASSERT_TRUE(run.r.found);
	// out of reach from the station in front of the table ...
	EXPECT_TRUE(d.needed);
	ASSERT_FALSE(d.reasons_before.empty());
	EXPECT_NE(d.reasons_before.front().find("out of reach"), std::string::npos)
	    << d.reasons_before.front();
	// ... in reach from behind it, where the robot drove and recognised it again
	EXPECT_TRUE(d.planned);
	EXPECT_EQ(d.chosen.side, "table.main +z side");
	EXPECT_TRUE(d.reached) << d.reason;
	EXPECT_TRUE(run.r.success) << run.r.failure;
	const auto& g = run.report["retrieval"];
	EXPECT_EQ(g["docking"]["side"], "table.main +z side");
	EXPECT_EQ(g["frame"], g["docking"]["frame"]);
	EXPECT_TRUE(run.report["eval"]["object_retrieved"].get<bool>());
	EXPECT_LT(g["grasp_error_mm"].get<double>(), 10.0);
	EXPECT_TRUE(run.report["eval"]["collision"].is_null());
	EXPECT_TRUE(run.report["eval"]["objects_disturbed"].empty());
}

TEST(RetrievalMission, WhenNoDockingPoseReachesTheFailureSaysSoAndTheArmStays)
{
	auto cfg = mission::test::defaultMissionConfig();
	// the arm's column 1.5 m behind the head: no pose round the table brings the cube in reach
	cfg.write("arm_mount", "T_C0inA", "0 0 1 1500    1 0 0 100    0 1 0 711");
	const auto run = mission::test::runMission(cfg, mission::test::shortRoute());
	const auto& d = run.r.docking;
	ASSERT_TRUE(run.r.found);
	EXPECT_TRUE(d.needed);
	EXPECT_FALSE(d.planned);
	EXPECT_GT(d.candidates, 0);
	EXPECT_EQ(d.candidates_checked, d.candidates);
	EXPECT_FALSE(run.r.retrieval.attempted);
	EXPECT_NE(run.r.failure.find("docking: none of"), std::string::npos) << run.r.failure;
	EXPECT_EQ(run.report["retrieval"]["docking"]["planned"], false);
	EXPECT_TRUE(run.r.returned_home);
}

TEST(RetrievalMission, ADockingPoseTooNearTheWallsIsLeftOutAndTheReasonNamed)
{
	// the office's cup stands at the desk's end, 0.5 m from the front wall and next to a filing
	// cabinet: the only poses from which the arm reaches it leave the base no room to turn
	auto cfg = mission::test::defaultMissionConfig();
	cfg.write("mission", "target", "cup");
	const std::string office = std::string(MROLR_SOURCE_DIR) + "/maps/office";
	const auto run = mission::test::runMission(
	    cfg, mission::test::planWith({}, office + "/plan.ini"), office + "/world.ini");
	const auto& d = run.r.docking;
	ASSERT_TRUE(run.r.found);
	EXPECT_TRUE(d.needed);
	EXPECT_GT(d.candidates_near_walls, 0);
	EXPECT_FALSE(d.planned);
	EXPECT_NE(run.r.failure.find("too near the room's walls"), std::string::npos) << run.r.failure;
	EXPECT_FALSE(run.r.arm_docked);
	EXPECT_TRUE(run.report["eval"]["collision"].is_null());
	EXPECT_TRUE(run.r.returned_home);
}

TEST(RetrievalMission, AFalseMatchAtTheStationIsFoundOutAtTheDockAndTheTableSweptAgain)
{
	// seed 11: the station's sweep takes something 0.56 m from the cube for it; at the docking
	// pose for that sighting the cube is not seen, the table is swept again from there, the real
	// cube found out of reach, and the base docks once more for it
	auto cfg = mission::test::defaultMissionConfig();
	cfg.write("mission", "seed", "11");
	const auto run = mission::test::runMission(cfg);
	const auto& d = run.r.docking;
	ASSERT_TRUE(run.r.found);
	EXPECT_GT(run.report["object_translation_error_mm"].get<double>(), 100.0)
	    << "the station's sighting was right: this seed no longer tests a false match";
	EXPECT_TRUE(d.swept_again);
	EXPECT_TRUE(d.docked_again);
	EXPECT_TRUE(run.r.success) << run.r.failure;
	EXPECT_TRUE(run.report["eval"]["object_retrieved"].get<bool>());
	EXPECT_LT(run.report["retrieval"]["grasp_error_mm"].get<double>(), 10.0);
}

/** The thesis's other objects on the lab (thesis 7.2–7.3: the bottle and the cup), the short
 * route, seed 1: recognised with the built models, grasped where the jaws must straddle them, put
 * on the deck, home. */
class ThesisObject : public ::testing::TestWithParam<const char*>
{
};

TEST_P(ThesisObject, IsRetrievedAndPutOnTheDeck)
{
	auto cfg = mission::test::defaultMissionConfig();
	cfg.write("mission", "target", GetParam());
	const auto run = mission::test::runMission(cfg, mission::test::shortRoute());
	EXPECT_TRUE(run.r.success) << run.r.failure;
	EXPECT_TRUE(run.report["eval"]["object_retrieved"].get<bool>());
	EXPECT_TRUE(run.report["eval"]["object_on_board"].get<bool>());
	EXPECT_LT(run.report["retrieval"]["grasp_error_mm"].get<double>(), 10.0);
	EXPECT_LT(run.report["retrieval"]["dock_calibration_error_mm"].get<double>(), 5.0);
	EXPECT_TRUE(run.report["eval"]["collision"].is_null());
	EXPECT_FALSE(run.r.arm_docked_home) << "the arm's platform is de-coupled for the drive home";
}

INSTANTIATE_TEST_SUITE_P(Lab, ThesisObject, ::testing::Values("can", "bottle", "cup"));

TEST(RetrievalMission, AVerifiedGraspTurnedAboutTheCanIsReachedOverItWithoutKnockingItOver)
{
	// the office, seed 8: the verification turns the can's pose 45° about its axis, and the
	// verified pre-grasp stands above the can while the first stood beside it; the straight line
	// between them cut through the can's top (it fell over); over the top it is held
	auto cfg = mission::test::defaultMissionConfig();
	cfg.write("mission", "target", "can");
	cfg.write("mission", "seed", "8");
	const std::string office = std::string(MROLR_SOURCE_DIR) + "/maps/office";
	const auto run = mission::test::runMission(
	    cfg, mission::test::planWith({}, office + "/plan.ini"), office + "/world.ini");
	const auto& g = run.r.retrieval;
	ASSERT_TRUE(g.correction_applied) << "no correction: this seed no longer tests the crossing";
	EXPECT_EQ(g.correction_route.size(), 3u) << "up, across, down";
	for (const auto& e : run.report["eval"]["gripper_events"])
		EXPECT_NE(e["kind"], "knocked_over") << e["detail"];
	EXPECT_TRUE(run.r.success) << run.r.failure;
	EXPECT_TRUE(run.report["eval"]["object_retrieved"].get<bool>());
}
