// The shipped worlds' routes against the base's footprint (sim::CollisionWorld): driven leg by leg
// as the planner drives them (rotate, translate, rotate; base::planLeg), nothing is touched.
#include <mrolr/base/TrajectoryPlanner.h>
#include <mrolr/sim/Collisions.h>
#include <mrolr/sim/SimBase.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <optional>

using namespace mrolr;

namespace
{
const std::string kMaps = std::string(MROLR_SOURCE_DIR) + "/maps/";

base::LabmateModel noiseless()
{
	base::LabmateOptions o;
	o.velocity_noise_fraction = 0;
	return base::LabmateModel(o);
}

Eigen::Vector3d poseOf(const world::Waypoint& w) { return {w.z_m, w.x_m, w.phi_rad}; }

/** Every planned step of the route (waypoints in file order), as the planner would drive it. */
std::vector<base::PlannedStep> routeSteps(const world::World& w, const base::LabmateModel& model)
{
	std::vector<base::PlannedStep> steps;
	Eigen::Vector3d pose = poseOf(w.waypoints.front());
	for (size_t i = 1; i < w.waypoints.size(); ++i)
	{
		for (const auto& s : base::planLeg(pose, poseOf(w.waypoints[i]), model, {}))
		{
			steps.push_back(s);
			pose = model.move(pose, s.u);
		}
	}
	return steps;
}

/** Drives the route with a noiseless, slip-free base that collides; the first contact, if any. */
std::optional<sim::Contact> driveRoute(const world::World& w)
{
	const auto model = noiseless();
	sim::SimBaseOptions o;
	o.slip_probability = 0;
	sim::SimBase base(model, o, poseOf(w.waypoints.front()));
	base.setCollisionWorld(std::make_shared<sim::CollisionWorld>(w, o.footprint));
	for (const auto& s : routeSteps(w, model))
	{
		base.step(s.u);
		if (base.lastContact() || base.odometry().bumper) break;
	}
	if (!base.lastContact() && base.odometry().bumper)  // within bumper travel, not stopped
		return sim::Contact{"bumper", base.truePose().head<2>(), base.truePose(), 1.0};
	return base.lastContact();
}

/** Poses every few millimetres (at any footprint point) along the route. */
std::vector<Eigen::Vector3d> routePoses(const world::World& w, double radius_m)
{
	const auto model = noiseless();
	std::vector<Eigen::Vector3d> poses{poseOf(w.waypoints.front())};
	for (const auto& s : routeSteps(w, model))
	{
		const double sweep = std::abs(model.arcLength(s.u)) + radius_m * std::abs(model.turnAngle(s.u));
		const int n = std::max(1, int(std::ceil(sweep / 0.005)));
		const Eigen::Vector3d from = poses.back();
		for (int k = 1; k <= n; ++k)
			poses.push_back(model.move(from, {s.u.v1_mps, s.u.v2_mps, s.u.dt_s * k / n}));
	}
	return poses;
}

std::string where(const sim::Contact& c)
{
	return c.what + " at (z, x) = (" + std::to_string(c.p_zx_m[0]) + ", " +
	       std::to_string(c.p_zx_m[1]) + "), base stopped at (" +
	       std::to_string(c.last_free_zxphi[0]) + ", " + std::to_string(c.last_free_zxphi[1]) +
	       ", " + std::to_string(c.last_free_zxphi[2] * 180 / M_PI) + " deg)";
}

/** Distance from the table waypoint to the front edge of the mission's table, along its heading. */
double frontEdgeDistance(const world::Table& t, const world::Waypoint& wp)
{
	const double yaw = t.yaw_deg * M_PI / 180;
	const Eigen::Vector2d own_z(std::cos(yaw), std::sin(yaw));
	return (Eigen::Vector2d(t.z_m, t.x_m) - Eigen::Vector2d(wp.z_m, wp.x_m)).dot(own_z) -
	       t.depth_m / 2;
}
}  // namespace

TEST(WorldRoutes, OfficeRouteTouchesNothing)
{
	const auto w = world::World::load(kMaps + "office/world.ini");
	const auto c = driveRoute(w);
	EXPECT_FALSE(c) << where(*c);
}

TEST(WorldRoutes, LabRouteTouchesNothing)
{
	const auto w = world::World::load(kMaps + "lab/world.ini");
	const auto c = driveRoute(w);
	EXPECT_FALSE(c) << where(*c);
}

TEST(WorldRoutes, OfficeRouteKeepsHalfAMetreFromEverythingButTheDeskAtItsWaypoint)
{
	const auto w = world::World::load(kMaps + "office/world.ini");
	const sim::CollisionWorld cw(w, {});
	const auto* desk_wp = w.findWaypoint(w.mission.table_waypoint);
	ASSERT_TRUE(desk_wp);
	const Eigen::Vector2d at_desk(desk_wp->z_m, desk_wp->x_m);
	double nearest = 1e9;
	for (const auto& p : routePoses(w, cw.footprintRadius()))
	{
		const auto c = cw.clearanceAt(p);
		// facing the desk's front edge 0.55 m away, the base is meant to be close to it
		if (c.what == "table.desk" && (p.head<2>() - at_desk).norm() < 0.5) continue;
		nearest = std::min(nearest, c.distance_m);
		ASSERT_GE(c.distance_m, 0.5) << c.what << " at (" << p.transpose() << ")";
	}
	EXPECT_LT(nearest, 0.8);  // the check saw the walls it passes
}

TEST(WorldRoutes, TableWaypointsFaceTheirTableWithTheCubeInReachOnTheFrontRow)
{
	for (const std::string name : {"lab", "office"})
	{
		SCOPED_TRACE(name);
		const auto w = world::World::load(kMaps + name + "/world.ini");
		const auto* wp = w.findWaypoint(w.mission.table_waypoint);
		const auto* cube = w.findObject("alphabet_cube");
		ASSERT_TRUE(wp && cube);
		const auto* t = w.findTable(cube->table);
		ASSERT_TRUE(t);
		const double d = frontEdgeDistance(*t, *wp);
		EXPECT_GE(d, 0.5);
		EXPECT_LE(d, 0.6);
		EXPECT_NEAR(base::wrapAngle(wp->phi_rad - t->yaw_deg * M_PI / 180), 0, 5 * M_PI / 180);
		// the cube 0.2 m behind the front edge, within 0.25 m of the waypoint's heading line
		const Eigen::Vector2d fwd(std::cos(wp->phi_rad), std::sin(wp->phi_rad));
		const Eigen::Vector2d rel(cube->z_m - wp->z_m, cube->x_m - wp->x_m);
		EXPECT_NEAR(rel.dot(fwd), d + 0.2, 0.03);
		EXPECT_LT(std::abs(rel.dot(Eigen::Vector2d(-fwd[1], fwd[0]))), 0.25);
	}
}
