// The robot on its own: a table it was not told of stops it by the bumper (and eval names what it
// hit), a slipped turn makes it lost and it finds the map again through a known feature, and it
// drives the office (another room, route and table) from its images with the office's plan.
#include "MissionTestConfig.h"

#include <mrolr/eval/MissionOutputs.h>

#include <gtest/gtest.h>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>

#include <filesystem>
#include <fstream>

using namespace mrolr;
namespace fs = std::filesystem;
using mission::test::timelineHas;

TEST(HonestRun, ATableTheRobotWasNotToldOfStopsItByTheBumperAndEvalNamesIt)
{
	// The plan has no table, and its route runs straight through the lab's.
	const auto dir = mission::test::freshTempDir("honest_run_test_collision");
	std::ofstream(dir + "/plan.ini") << "[plan]\nroute = W0 T\nstations = W5\nhome = W6\n"
	                                    "[waypoints]\nW0 = 0 0 0\nT = 2.4 0 0\nW5 = 0.5 0 0\n"
	                                    "W6 = 0 0 0\n";
	auto cfg = mission::test::defaultMissionConfig();
	cfg.write("mission", "obstacle_mode", "false");
	const auto run = mission::test::runMission(cfg, mission::test::planWith({}, dir + "/plan.ini"));
	EXPECT_TRUE(run.r.collided);
	EXPECT_TRUE(run.r.stopped);
	EXPECT_FALSE(run.r.success);
	EXPECT_NE(run.r.failure.find("bumper"), std::string::npos) << run.r.failure;
	const auto& c = run.report["eval"]["collision"];
	ASSERT_FALSE(c.is_null());
	EXPECT_EQ(c["what"], "table.main");
	EXPECT_NEAR(c["z_m"].get<double>(), 1.05, 0.05);  // the table's front edge
	EXPECT_NE(run.report["failure"].get<std::string>().find("hit table.main"), std::string::npos);
	EXPECT_FALSE(run.report["success"].get<bool>());
	// The robot stopped there: its last step is the one that met the table.
	EXPECT_LT(run.truth.final_zxphi.x(), 1.05);
	const auto out = eval::writeMissionOutputs(run.r, run.o, &run.truth, dir + "/out");
	EXPECT_GT(fs::file_size(dir + "/out/trajectory.png"), 100u);
}

TEST(HonestRun, ASlippedTurnLosesTheRobotAndAKnownFeatureFindsTheMapAgain)
{
	auto cfg = mission::test::defaultMissionConfig();
	cfg.write("sim_base", "kick_after_s", "300");  // the first turn after 300 s of driving ...
	cfg.write("sim_base", "kick_deg", "20");       // ... turns 20 deg more than its wheels did
	cfg.write("search", "scene_sensor", "exact_sim");  // navigation is under test here
	cfg.write("search", "render_stereo", "false");
	const auto run = mission::test::runMission(cfg);
	EXPECT_GE(run.r.lost_events, 1);
	EXPECT_GE(run.r.recoveries, 1);
	EXPECT_TRUE(timelineHas(run.r, "lost: ")) << "the robot did not notice";
	EXPECT_TRUE(timelineHas(run.r, "found again via ")) << "no known feature found it again";
	EXPECT_TRUE(run.r.success) << run.r.failure;
	EXPECT_LT(run.report["final_position_error_m"].get<double>(), 0.15);
	EXPECT_EQ(run.report["lost_events"], run.r.lost_events);
	// trajectory.png marks where the robot said it was lost (the legend's "lost" star colour)
	const auto dir = mission::test::freshTempDir("honest_run_test_lost");
	eval::writeMissionOutputs(run.r, run.o, &run.truth, dir);
	const cv::Mat png = cv::imread(dir + "/trajectory.png");
	ASSERT_FALSE(png.empty());
	cv::Mat lost_colour;
	const int legend_px = 312;  // the legend panel and margin on the right (io/TopViewPlot)
	cv::inRange(png(cv::Rect(0, 0, png.cols - legend_px, png.rows)), cv::Scalar(0, 200, 255),
	            cv::Scalar(0, 200, 255), lost_colour);
	EXPECT_GT(cv::countNonZero(lost_colour), 10);  // a star on the data, not only in the legend
}

TEST(HonestRun, TheOfficeIsDrivenFromImagesWithItsOwnPlan)
{
	auto cfg = mission::test::defaultMissionConfig();
	const std::string office = std::string(MROLR_SOURCE_DIR) + "/maps/office";
	cfg.write("mission", "seed", "3");
	const auto run = mission::test::runMission(
	    cfg, mission::test::planWith({}, office + "/plan.ini"), office + "/world.ini");
	EXPECT_EQ(run.r.navigation_source, "images");
	EXPECT_TRUE(run.r.success) << run.r.failure;
	EXPECT_TRUE(run.report["eval"]["confirms"].get<bool>());
	EXPECT_LT(run.report["final_position_error_m"].get<double>(), 0.15);
	EXPECT_TRUE(run.report["eval"]["object_retrieved"].get<bool>());
	EXPECT_TRUE(run.report["eval"]["collision"].is_null());
}
