// The robot's plan: what save() writes load() reads back the same, patches and viewpoints
// included; overrides replace keys; a malformed line names file, line, section and key.
#include <mrolr/mission/Plan.h>

#include "../common/ThrownMessage.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

using namespace mrolr::mission;
namespace fs = std::filesystem;

namespace
{
Plan samplePlan()
{
	Plan p;
	p.waypoints = {{"A", {0, 0, 0}}, {"B", {1.5, -0.5, M_PI / 2}}, {"S", {2, 0, -M_PI / 4}}};
	p.route = {p.waypoints[0], p.waypoints[1]};
	p.stations = {p.waypoints[2]};
	p.home = p.waypoints[0];
	PlanFeature k;
	k.id = "F7", k.p_FinW = {0.5, 1.7, 4.2}, k.sigma_m = {0.01, 0.002, 0.03};
	k.patch = cv::Mat(13, 13, CV_8UC1);
	cv::randu(k.patch, 0, 255);
	k.patch_file = "patches/F7.png", k.p_viewinW = Eigen::Vector3d(0.1, 1.0, 0.2);
	p.known_features = {k};
	p.tables = {{"t", 0.2, 1.4, 15, 1.2, 0.8, 0.7}};
	p.room = PlanRoom{-3, -2, 3, 6};
	return p;
}
}  // namespace

TEST(Plan, SaveThenLoadGivesTheSamePlan)
{
	const auto dir = fs::temp_directory_path() / "mrolr_plan_test";
	fs::remove_all(dir);
	fs::create_directories(dir);
	const Plan p = samplePlan();
	p.save((dir / "plan.ini").string());
	const Plan q = Plan::load((dir / "plan.ini").string());
	ASSERT_EQ(q.waypoints.size(), 3u);
	EXPECT_LT((q.waypoints[1].xv_zxphi - p.waypoints[1].xv_zxphi).norm(), 1e-9);
	ASSERT_EQ(q.route.size(), 2u);
	EXPECT_EQ(q.stations[0].name, "S");
	EXPECT_EQ(q.home.name, "A");
	ASSERT_EQ(q.known_features.size(), 1u);
	const auto& k = q.known_features[0];
	EXPECT_LT((k.p_FinW - p.known_features[0].p_FinW).norm(), 1e-5);
	EXPECT_LT((k.sigma_m - p.known_features[0].sigma_m).norm(), 1e-6);
	EXPECT_EQ(cv::norm(k.patch, p.known_features[0].patch, cv::NORM_INF), 0);
	ASSERT_TRUE(k.p_viewinW.has_value());
	EXPECT_LT((*k.p_viewinW - *p.known_features[0].p_viewinW).norm(), 1e-5);
	ASSERT_EQ(q.tables.size(), 1u);
	EXPECT_DOUBLE_EQ(q.tables[0].yaw_deg, 15);
	EXPECT_DOUBLE_EQ(q.tables[0].top_height_m, 0.7);
	ASSERT_TRUE(q.room.has_value());
	EXPECT_DOUBLE_EQ(q.room->min_z_m, -2);
	EXPECT_DOUBLE_EQ(q.room->max_x_m, 3);
}

TEST(Plan, TheWallDistanceIsToTheNearestWallAndNegativeOutside)
{
	const PlanRoom room{-3, -2, 3, 6};  // x from -3 to 3, z from -2 to 6
	EXPECT_DOUBLE_EQ(room.wallDistance({0, 0}), 2.0);     // (z, x): the back wall
	EXPECT_DOUBLE_EQ(room.wallDistance({5.5, 0}), 0.5);   // the front wall
	EXPECT_DOUBLE_EQ(room.wallDistance({1, -2.75}), 0.25);  // the right wall
	EXPECT_LT(room.wallDistance({7, 0}), 0);
}

TEST(Plan, OverridesReplaceAndAddKeys)
{
	const auto dir = fs::temp_directory_path() / "mrolr_plan_test_over";
	fs::remove_all(dir);
	fs::create_directories(dir);
	samplePlan().save((dir / "plan.ini").string());
	const Plan q = Plan::load((dir / "plan.ini").string(),
	                          {{"waypoints", "C", "3 1 180"}, {"plan", "stations", "S C"}});
	ASSERT_EQ(q.stations.size(), 2u);
	EXPECT_NEAR(q.stations[1].xv_zxphi.z(), M_PI, 1e-12);
}

TEST(Plan, MalformedEntriesNameFileLineSectionAndKey)
{
	const auto dir = fs::temp_directory_path() / "mrolr_plan_test_bad";
	fs::create_directories(dir);
	auto errorOf = [&](const std::string& text)
	{
		std::ofstream(dir / "plan.ini") << text;
		return mrolr::test_support::messageOf<std::exception>(
		    [&] { Plan::load((dir / "plan.ini").string()); });
	};
	const std::string head = "[plan]\nroute = A\nstations = A\nhome = A\n[waypoints]\n";
	EXPECT_NE(errorOf(head + "A = 0 0\n").find("plan.ini:6 [waypoints] A"), std::string::npos);
	EXPECT_NE(errorOf(head + "A = 0 0 0\n[known_features]\nk = 1 2 3 nope.png 1 1 1\n")
	              .find("cannot read the patch"),
	          std::string::npos);
	EXPECT_NE(errorOf(head + "A = 0 0 0\n[known_features]\nk = 1 2 3 p.png 1 -1 1\n")
	              .find("must not be negative"),
	          std::string::npos);
	EXPECT_NE(errorOf("[plan]\nroute = A\nstations = A\nhome = A\n[waypoints]\nB = 0 0 0\n")
	              .find("no waypoint 'A'"),
	          std::string::npos);
	EXPECT_NE(errorOf(head + "A = 0 0 0\n[plans]\n").find("unknown section"), std::string::npos);
	EXPECT_NE(errorOf(head + "A = 0 0 0\n[room]\nmin_m = 0 0\nmax_m = 5 -1\n")
	              .find("[room] max_m"),
	          std::string::npos);
	EXPECT_NE(errorOf(head + "A = 0 0 0\n[room]\nmin_m = 0 0\n").find("max_m"), std::string::npos);
	EXPECT_NE(errorOf("[waypoints]\nA = 0 0 0\n").find("missing section [plan]"), std::string::npos);
	EXPECT_NE(errorOf(head + "A = 0 0 0\n[table.t]\ncentre_m = 0 1\nsize_m = 1 0 1\n")
	              .find("[table.t] size_m"),
	          std::string::npos);
}
