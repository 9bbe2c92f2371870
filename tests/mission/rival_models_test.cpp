// [search] rival_models: a target answer another model of the database explains better is refused
// in its view, and the arm does not go for it (recog/Rivals.h, docs/mission.md "Rival models").
#include "MissionTestConfig.h"

#include <gtest/gtest.h>

using namespace mrolr;
using mission::test::timelineHas;

TEST(RivalModels, ACanPoseAtTheLargeCupsPlaceIsRefusedAndNotGrasped)
{
	// the fixed pans of thesis 6.4: on seed 4 the view at pan 10 deg takes the large cup for the
	// can (docs/mission.md); its own model is found there with a higher image score
	auto cfg = mission::test::defaultMissionConfig();
	cfg.write("mission", "target", "can");
	cfg.write("mission", "seed", "4");
	cfg.write("search", "cover_table", "false");
	cfg.write("search", "rival_models", "true");
	const auto run = mission::test::runMission(cfg);
	EXPECT_TRUE(timelineHas(run.r, "refused: the large_cup model explains that place better"));
	EXPECT_FALSE(run.r.retrieval.attempted);  // the arm never moved towards the large cup
	EXPECT_FALSE(run.r.success);
	EXPECT_NE(run.r.failure.find("not found"), std::string::npos) << run.r.failure;
	EXPECT_TRUE(run.r.returned_home);
}
