// Obstacle mode in whole missions (thesis 5.8.1.2, fig 5.8.1.4) on the lab with a box on the route:
// with it the robot goes round the box, out to the table and back home; without it the straight
// route runs through the box. Checked geometrically on the true path.
#include "MissionTestConfig.h"

#include <mrolr/mission/Mission.h>

#include <gtest/gtest.h>
#include <mrpt/config/CConfigFileMemory.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

using namespace mrolr;

namespace
{
/** Half the Labmate's width (m): the obstacle corridor's half width less its 5 cm margin. */
double robotHalfWidth(const mission::MissionOptions& o)
{
	return o.obstacle.corridor_half_width_m - 0.05;
}

mrpt::config::CConfigFileMemory obstacleMission()
{
	return mission::test::missionConfig("mission_obstacle.ini");
}

/** Distance (m) from (z, x) in W to the box's footprint; 0 inside. */
double distanceToBox(const world::Obstacle& b, const Eigen::Vector2d& p_zx)
{
	const double yaw = b.yaw_deg * M_PI / 180.0;
	const Eigen::Vector2d d = p_zx - Eigen::Vector2d(b.z_m, b.x_m);
	const double along_z = d.dot(Eigen::Vector2d(std::cos(yaw), std::sin(yaw)));
	const double along_x = d.dot(Eigen::Vector2d(-std::sin(yaw), std::cos(yaw)));
	return std::hypot(std::max(std::abs(along_z) - b.size_m.z() / 2, 0.0),
	                  std::max(std::abs(along_x) - b.size_m.x() / 2, 0.0));
}

/** Smallest distance of the true path (between samples every centimetre) to the box. */
double clearance(const mission::test::Run& run, const world::Obstacle& b)
{
	const auto path = mission::test::truePath(run);
	double best = 1e9;
	for (size_t i = 1; i < path.size(); ++i)
	{
		const Eigen::Vector2d a = path[i - 1].head<2>(), c = path[i].head<2>();
		const int n = std::max(1, static_cast<int>((c - a).norm() / 0.01));
		for (int k = 0; k <= n; ++k)
			best = std::min(best, distanceToBox(b, a + (c - a) * (double(k) / n)));
	}
	return best;
}

world::Obstacle box()
{
	const auto w = world::World::load(std::string(MROLR_SOURCE_DIR) + "/maps/lab_obstacle/world.ini");
	for (const auto& b : w.obstacles)
		if (b.name == "box") return b;
	throw std::runtime_error("maps/lab_obstacle has no [obstacle.box]");
}
}  // namespace

TEST(ObstacleMission, TheRobotGoesRoundTheBoxToTheTableAndBackHome)
{
	const auto run = mission::test::runMission(obstacleMission());
	const auto& o = run.o;
	const auto& r = run.r;
	ASSERT_TRUE(o.obstacle_mode);
	EXPECT_TRUE(r.found) << r.failure;
	EXPECT_TRUE(r.retrieved) << r.failure;
	EXPECT_TRUE(r.returned_home) << r.failure;
	EXPECT_TRUE(run.report["eval"]["collision"].is_null());
	// seen on the way out and again on the way back, and never touched
	EXPECT_GE(r.obstacle.events.size(), 2u);
	EXPECT_EQ(r.obstacle.failed_looks, 0);
	EXPECT_GT(clearance(run, box()), robotHalfWidth(o));
	// the first sighting, from the start 1.0 m before the box: near edge and width measured
	ASSERT_FALSE(r.obstacle.events.empty());
	const auto& s = r.obstacle.events.front().sighting;
	EXPECT_NEAR(s.near_m, 1.0, 0.1);
	EXPECT_NEAR(s.left_m - s.right_m, box().size_m.x(), 0.15);
}

TEST(ObstacleMission, WithoutObstacleModeTheRobotRunsIntoTheBoxAndSaysSo)
{
	auto cfg = obstacleMission();
	cfg.write("mission", "obstacle_mode", "false");
	const auto run = mission::test::runMission(cfg);
	const auto& r = run.r;
	EXPECT_TRUE(r.obstacle.events.empty());
	EXPECT_TRUE(r.collided);
	EXPECT_TRUE(r.stopped);
	EXPECT_FALSE(r.success);
	EXPECT_NE(r.failure.find("bumper"), std::string::npos) << r.failure;
	ASSERT_FALSE(run.report["eval"]["collision"].is_null());
	EXPECT_EQ(run.report["eval"]["collision"]["what"], "obstacle.box");
	EXPECT_FALSE(run.report["success"].get<bool>());
}
