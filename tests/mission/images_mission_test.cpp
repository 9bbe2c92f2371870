// The short mission with navigation measurements made in the rendered stereo pairs
// ([navigation] landmark_sensor = images): the vision area's features, patches and matches.
#include "MissionTestConfig.h"

#include <mrolr/mission/Mission.h>

#include <gtest/gtest.h>

using namespace mrolr;

TEST(MissionImages, DefaultMissionLocalisesFromItsOwnImageFeatures)
{
	auto cfg = mission::test::defaultMissionConfig();
	const auto run = mission::test::runMission(cfg, mission::test::shortRoute());
	const auto& r = run.r;
	EXPECT_TRUE(r.success) << r.failure;
	EXPECT_GT(r.navigation_pairs, r.image_searches);  // acquisitions grab pairs too
	EXPECT_GT(r.image_searches, 20);
	EXPECT_GE(r.image_matches, r.measurements);  // a measurement needs a match in both images
	EXPECT_GT(r.measurements, static_cast<int>(0.8 * r.image_searches));
	// The map holds the plan's known features and those acquired in the images.
	ASSERT_FALSE(r.map.empty());
	size_t known = 0;
	for (const auto& f : r.map) known += f.known;
	EXPECT_EQ(known, run.o.plan.known_features.size());
	EXPECT_GT(r.map.size(), known);
	EXPECT_LT(run.report["final_estimate_error_m"].get<double>(), 0.1);
	// Rendering is the simulator's time, kept out of the robot's compute.
	EXPECT_GT(r.timeline.renderSeconds(), 0);
	// Navigation pairs are not recorded; the table's views, the obstacle looks' and the dock
	// calibration's pairs are.
	EXPECT_EQ(r.shots.size(),
	          mission::countShots(r.shots, mission::StereoShot::Purpose::Obstacle) +
	              mission::countShots(r.shots, mission::StereoShot::Purpose::Calibration) +
	              static_cast<size_t>(r.search.views) + 1);
	EXPECT_EQ(mission::countShots(r.shots, mission::StereoShot::Purpose::Calibration),
	          r.dock_calibration.frames.size());
}

// [navigation] image_nssd_ambiguity_margin reaches the vision options of the images mode only;
// absent, the vision file's value stays; out of range names the key.
TEST(MissionImages, AmbiguityMarginReplacesTheVisionFilesValue)
{
	auto cfg = mission::test::defaultMissionConfig();
	cfg.write("navigation", "image_nssd_ambiguity_margin", "0.25");
	EXPECT_DOUBLE_EQ(mission::test::optionsFrom(cfg).vision.nssd_ambiguity_margin, 0.25);
	cfg.write("navigation", "image_nssd_ambiguity_margin", "-1");
	EXPECT_DOUBLE_EQ(mission::test::optionsFrom(cfg).vision.nssd_ambiguity_margin, 0);
	cfg.write("navigation", "image_nssd_ambiguity_margin", "9");
	try
	{
		mission::test::optionsFrom(cfg);
		FAIL() << "a margin of 9 was accepted";
	}
	catch (const std::exception& e)
	{
		EXPECT_NE(std::string(e.what()).find("image_nssd_ambiguity_margin"), std::string::npos)
		    << e.what();
	}
}
