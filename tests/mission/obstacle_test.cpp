// Obstacle mode (thesis 5.8.1.2, fig 5.8.1.4): the [obstacle] options, the detour geometry on
// point sets, and detection from rendered stereo pairs of the lab with a box on the route.
#include "MissionTestConfig.h"

#include <mrolr/geometry/Frames.h>
#include <mrolr/mission/ObstacleAvoidance.h>
#include <mrolr/sim/SceneBuilder.h>
#include <mrolr/sim/StereoRenderer.h>
#include <mrolr/util/Config.h>

#include <gtest/gtest.h>

using namespace mrolr;
using mission::ObstacleOptions;

namespace
{
mrpt::config::CConfigFileMemory obstacleConfig()
{
	return mission::test::missionConfig("mission_obstacle.ini");
}

ObstacleOptions obstacleOptions()
{
	const auto cfg = obstacleConfig();
	ObstacleOptions o;
	o.loadFromConfigFile(cfg, "obstacle");
	return o;
}

/** A box of points (B, m): every 2 cm over its front face and its top. */
std::vector<Eigen::Vector3d> boxPoints(double x0, double x1, double z0, double z1, double h)
{
	std::vector<Eigen::Vector3d> p;
	for (double x = x0; x <= x1; x += 0.02)
	{
		for (double y = 0.1; y <= h; y += 0.02) p.emplace_back(x, y, z0);
		for (double z = z0; z <= z1; z += 0.02) p.emplace_back(x, h, z);
	}
	return p;
}

void append(std::vector<Eigen::Vector3d>& a, const std::vector<Eigen::Vector3d>& b)
{
	a.insert(a.end(), b.begin(), b.end());
}
}  // namespace

TEST(ObstacleOptions, ConfigLoadsAndAnEvenBlockIsRejected)
{
	const auto o = obstacleOptions();
	EXPECT_DOUBLE_EQ(o.range_m, 1.0);
	auto cfg = obstacleConfig();
	cfg.write("obstacle", "block_size_px", 4);
	ObstacleOptions bad;
	try
	{
		bad.loadFromConfigFile(cfg, "obstacle");
		FAIL() << "an even block size was accepted";
	}
	catch (const util::ConfigError& e)
	{
		EXPECT_NE(std::string(e.what()).find("[obstacle] block_size_px"), std::string::npos)
		    << e.what();
	}
}

TEST(ObstacleDetour, BoxLeftOfTheRouteIsPassedOnTheRight)
{
	const auto o = obstacleOptions();
	const auto p = boxPoints(-0.15, 0.35, 0.9, 1.3, 0.6);
	const auto s = mission::obstacleAhead(p, 2.0, o);
	ASSERT_TRUE(s.blocked);
	EXPECT_NEAR(s.near_m, 0.9, 0.03);
	EXPECT_NEAR(s.far_m, 1.3, 0.05);
	EXPECT_NEAR(s.right_m, -0.15, 0.06);
	EXPECT_NEAR(s.left_m, 0.35, 0.06);
	const auto d = mission::planDetour(s, p, o);
	EXPECT_EQ(d.side, -1);
	EXPECT_FALSE(d.both_blocked);
	ASSERT_EQ(d.via_zx.size(), 2u);
	// both waypoints keep the robot's corridor clear of the box's side, and the second is past it
	const double pass = o.corridor_half_width_m + o.clearance_m;
	for (const auto& v : d.via_zx) EXPECT_NEAR(v.y(), s.right_m - pass, 1e-9);
	EXPECT_LT(d.via_zx[0].x(), s.near_m - o.corridor_half_width_m);
	EXPECT_GT(d.via_zx[1].x(), s.far_m + o.corridor_half_width_m);
}

TEST(ObstacleDetour, AWallOnTheShorterSideSendsTheRobotTheOtherWay)
{
	const auto o = obstacleOptions();
	auto p = boxPoints(-0.15, 0.35, 0.9, 1.3, 0.6);
	const auto s = mission::obstacleAhead(p, 2.0, o);
	// a second box 0.75 m right of the first: too narrow a gap for the robot's 0.8 m corridor
	append(p, boxPoints(-1.0, -0.9, 0.2, 2.0, 1.0));
	const auto d = mission::planDetour(s, p, o);
	EXPECT_GT(d.points_right, o.min_points);
	EXPECT_EQ(d.side, +1);
	EXPECT_NEAR(d.via_zx[0].y(), s.left_m + o.corridor_half_width_m + o.clearance_m, 1e-9);
}

TEST(ObstacleDetour, NothingInTheCorridorOrBeyondItsLengthIsNoObstacle)
{
	const auto o = obstacleOptions();
	EXPECT_FALSE(mission::obstacleAhead(boxPoints(0.6, 1.0, 0.5, 0.9, 0.6), 1.0, o).blocked);
	EXPECT_FALSE(mission::obstacleAhead(boxPoints(-0.2, 0.2, 1.2, 1.6, 0.6), 1.0, o).blocked);
	EXPECT_FALSE(mission::obstacleAhead({}, 1.0, o).blocked);
	// a box within range but beyond the robot standing at the leg's goal 0.3 m ahead is no
	// obstacle; one within the robot's radius of the goal is
	EXPECT_FALSE(mission::obstacleAhead(boxPoints(-0.2, 0.2, 0.8, 1.2, 0.6), 0.3, o, true).blocked);
	EXPECT_TRUE(mission::obstacleAhead(boxPoints(-0.2, 0.2, 0.6, 1.0, 0.6), 0.3, o, true).blocked);
}

TEST(ObstacleDetour, BaseToWorldTurnsWithTheHeading)
{
	// facing +x (φ = 90°), a point 1 m ahead and 0.5 m left is at z − 0.5, x + 1
	const auto p = mission::baseToWorld({2.0, 1.0, M_PI / 2}, {1.0, 0.5});
	EXPECT_NEAR(p.x(), 1.5, 1e-12);
	EXPECT_NEAR(p.y(), 2.0, 1e-12);
}

namespace
{
/** The lab with a box on the route, rendered from a vehicle pose (z, x, φ). */
struct RenderedLab
{
	mission::MissionOptions o =
	    mission::MissionOptions::load(mission::test::configDir() + "/mission_obstacle.ini");
	sim::LabScene lab = sim::buildLabScene(
	    world::World::load(std::string(MROLR_SOURCE_DIR) + "/maps/lab_obstacle/world.ini"));
	geometry::BiSightHead head{o.bisight};
	sim::StereoRenderer renderer{head, sim::RenderOptions()};
	Eigen::Vector3d xv = Eigen::Vector3d::Zero();
	mission::Timeline timeline;

	mission::ObstacleAvoidance avoidance()
	{
		return mission::ObstacleAvoidance(
		    head, o.obstacle,
		    [this](const geometry::HeadAngles& a)
		    {
			    const auto f =
			        renderer.render(*lab.scene, geometry::T_C0inW(xv, o.bisight.head_height_m), a);
			    return hw::StereoImages{f.left, f.right, a, 0};
		    },
		    timeline);
	}
};
}  // namespace

namespace
{
/** maps/lab_obstacle's box: its near face z, and its right and left edges x (W, m). */
struct BoxFaces
{
	double near_z, right_x, left_x;
};

BoxFaces boxFaces()
{
	const auto w = world::World::load(std::string(MROLR_SOURCE_DIR) + "/maps/lab_obstacle/world.ini");
	for (const auto& b : w.obstacles)
		if (b.name == "box")
			return {b.z_m - b.size_m.z() / 2, b.x_m - b.size_m.x() / 2, b.x_m + b.size_m.x() / 2};
	throw std::runtime_error("maps/lab_obstacle has no [obstacle.box]");
}
}  // namespace

TEST(ObstacleFromStereo, TheBoxOnTheRouteIsSeenMeasuredAndPassedOnItsOpenSide)
{
	RenderedLab lab;
	const BoxFaces box = boxFaces();
	lab.xv = {box.near_z - 0.9, 0.0, 0.0};  // the box's near face 0.9 m ahead, facing +z
	auto a = lab.avoidance();
	const auto via = a.check(lab.xv, {0.5, 0.0, 0.0});
	ASSERT_EQ(a.report().events.size(), 1u);
	const auto& e = a.report().events[0];
	EXPECT_NEAR(e.sighting.near_m, 0.9, 0.05);
	EXPECT_NEAR(e.sighting.right_m, box.right_x, 0.08);
	EXPECT_NEAR(e.sighting.left_m, box.left_x, 0.08);
	// the box stands more on the left of the route: it is passed on the right
	ASSERT_GT(box.left_x + box.right_x, 0);
	EXPECT_EQ(e.detour.side, -1);
	ASSERT_EQ(via.size(), 2u);
	EXPECT_EQ(a.report().looks, 3);
}

TEST(ObstacleFromStereo, NoObstacleWhenTheBoxIsBeyondRangeOrOffTheRoute)
{
	RenderedLab lab;
	const BoxFaces box = boxFaces();
	auto a = lab.avoidance();
	lab.xv = {box.near_z - 1.05, 0.0, 0.0};  // near face 1.05 m ahead, beyond the 1 m range
	EXPECT_TRUE(a.check(lab.xv, {0.5, 0.0, 0.0}).empty());
	lab.xv = {box.near_z - 0.9, 0.0, M_PI / 2};  // facing left, open floor
	EXPECT_TRUE(a.check(lab.xv, {box.near_z - 0.9, 2.0, M_PI / 2}).empty());
	EXPECT_EQ(a.report().looks, 2);
	EXPECT_TRUE(a.report().events.empty());
}

TEST(ObstacleFromStereo, TheMapsTablesAreNoObstacles)
{
	RenderedLab lab;
	// past the search station, turned towards the table's front edge and legs (as a robot that
	// overshot W5 does when it corrects)
	lab.xv = {0.78, 0.11, 1.19};
	const Eigen::Vector3d goal(lab.xv.x() + std::cos(1.19), lab.xv.y() + std::sin(1.19), 1.19);
	auto a = lab.avoidance();
	EXPECT_FALSE(a.check(lab.xv, goal).empty());  // unknown: a table is in the way
	a.setKnownTables(lab.o.plan.tables, lab.o.obstacle.table_margin_m);
	EXPECT_TRUE(a.check(lab.xv, goal).empty());  // from the map: known, not avoided
}
