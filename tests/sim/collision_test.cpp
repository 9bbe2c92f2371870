// The base's footprint against walls, tables and obstacles (sim::CollisionWorld in sim::SimBase).
#include <mrolr/sim/Collisions.h>
#include <mrolr/sim/SimBase.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

using namespace mrolr;

namespace
{
/** A 6 × 8 m room (x −3..3, z −2..6) with @p extra sections. */
world::World roomWith(const std::string& extra = "")
{
	return world::World::parse("[room]\nmin_m = -3 0 -2\nmax_m = 3 3 6\n[waypoints]\nW0 = 0 0 0\n" +
	                           extra);
}

/** A noiseless, slip-free base at @p start colliding with @p w. */
struct Rig
{
	base::LabmateModel model;
	sim::SimBase base;
	Rig(const world::World& w, const Eigen::Vector3d& start, const sim::Footprint& fp = {})
	    : model(noiseless()), base(model, slipFree(), start)
	{
		base.setCollisionWorld(std::make_shared<sim::CollisionWorld>(w, fp));
	}
	static base::LabmateModel noiseless()
	{
		base::LabmateOptions o;
		o.velocity_noise_fraction = 0;
		return base::LabmateModel(o);
	}
	static sim::SimBaseOptions slipFree()
	{
		sim::SimBaseOptions o;
		o.slip_probability = 0;
		return o;
	}
	/** Straight 20 cm steps (negative: backwards). */
	void drive(int steps, double step_m = 0.2)
	{
		for (int i = 0; i < steps; ++i) base.step(model.translationControl(step_m));
	}
};

/** Distance (m) from @p p to the boundary of the rectangle @p r. */
double distanceToOutline(const Eigen::Vector2d& p, const sim::CollisionWorld::Polygon& r)
{
	double d = 1e9;
	for (size_t i = 0; i < r.size(); ++i)
	{
		const Eigen::Vector2d a = r[i], ab = r[(i + 1) % r.size()] - a;
		const double t = std::clamp((p - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
		d = std::min(d, (a + t * ab - p).norm());
	}
	return d;
}
}  // namespace

TEST(Collisions, DrivenStraightAtAWallTheBaseStopsBeforeItWithTheBumperPressed)
{
	Rig rig(roomWith(), {4.05, 0.5, 0.0});  // front edge 1.55 m before the front wall z = 6
	EXPECT_FALSE(rig.base.odometry().bumper);
	rig.drive(12);  // 2.4 m asked
	const auto& c = rig.base.lastContact();
	ASSERT_TRUE(c);
	EXPECT_EQ(c->what, "wall");
	EXPECT_NEAR(c->p_zx_m[0], 6.0, 1e-3);  // on the wall,
	EXPECT_NEAR(c->p_zx_m[1], 0.5, 1e-3);  // in the middle of the front edge
	EXPECT_NEAR(rig.base.truePose()[0], 6.0 - 0.4, 2e-3);  // half the 0.8 m footprint before it
	EXPECT_LE(rig.base.truePose()[0] + 0.4, 6.0 + 1e-6);  // not into it
	EXPECT_TRUE(rig.base.odometry().bumper);
	// the wheels stalled at the contact: the encoders counted 1.55 m, not 2.4 m
	EXPECT_NEAR(rig.base.odometry().ticks_right / 20000.0, 1.55, 2e-3);
	EXPECT_NEAR(rig.base.odometry().xv_zxphi[0], rig.base.truePose()[0], 1e-3);
}

TEST(Collisions, DrivenIntoAYawedTableTheBaseStopsAndNamesIt)
{
	const auto w = roomWith("[table.desk]\ncentre_m = 0.2 2.5\nyaw_deg = 30\nsize_m = 1.2 0.6 0.75\n");
	Rig rig(w, {0, 0, 0});
	rig.drive(15);
	const auto& c = rig.base.lastContact();
	ASSERT_TRUE(c);
	EXPECT_EQ(c->what, "table.desk");
	const auto desk = sim::rectangleOnFloor(2.5, 0.2, 30 * M_PI / 180, 1.2, 0.6);
	EXPECT_LT(distanceToOutline(c->p_zx_m, desk), 2e-3);             // on the table's edge
	EXPECT_NEAR(c->p_zx_m[0], rig.base.truePose()[0] + 0.4, 2e-3);  // and at the base's front
	EXPECT_LT(rig.base.truePose()[0], 2.5);
	EXPECT_FALSE(sim::CollisionWorld(w, {}).touchAt(rig.base.truePose()));
	EXPECT_TRUE(rig.base.odometry().bumper);
}

TEST(Collisions, ARoutePassingATableWithClearanceTouchesNothing)
{
	const auto w = roomWith("[table.main]\ncentre_m = 0 1.5\nsize_m = 1.6 0.9 0.75\n");
	Rig rig(w, {-1.0, -1.2, 0});  // the footprint's side 5 cm clear of the table's end x = −0.8
	rig.drive(25);
	EXPECT_NEAR(rig.base.truePose()[0], 4.0, 1e-6);
	EXPECT_FALSE(rig.base.lastContact());
	EXPECT_FALSE(rig.base.odometry().bumper);
	const auto gap = sim::CollisionWorld(w, {}).clearanceAt({1.5, -1.2, 0});
	EXPECT_EQ(gap.what, "table.main");
	EXPECT_NEAR(gap.distance_m, 0.05, 1e-9);
}

TEST(Collisions, ATurnInPlaceThatWouldSwingTheFootprintIntoAWallIsStopped)
{
	// the left side 5 cm from the left wall x = 3; turning left swings the front-left corner out
	Rig rig(roomWith(), {2.0, 3.0 - 0.35 - 0.05, 0});
	rig.base.step(rig.model.rotationControl(M_PI / 2));
	const auto& c = rig.base.lastContact();
	ASSERT_TRUE(c);
	EXPECT_EQ(c->what, "wall");
	EXPECT_NEAR(c->p_zx_m[1], 3.0, 1e-3);
	// the corner (0.4, 0.35) reaches x = 3 when 0.4 sin φ + 0.35 cos φ = 0.4
	const double phi_contact = std::asin(0.4 / std::hypot(0.4, 0.35)) - std::atan2(0.35, 0.4);
	EXPECT_NEAR(rig.base.truePose()[2], phi_contact, 2e-3);
	EXPECT_TRUE(rig.base.odometry().bumper);
	rig.base.step(rig.model.rotationControl(-rig.base.truePose()[2]));  // turning back frees it
	EXPECT_FALSE(rig.base.odometry().bumper);
}

TEST(Collisions, ATwentyCentimetreStepCannotTunnelThroughAThinObstacle)
{
	// a 5 cm sheet; a footprint 10 cm long would be wholly past it after one 20 cm step
	const auto w = roomWith("[obstacle.sheet]\ncentre_m = 0 1.0\nsize_m = 1.0 1.0 0.05\n");
	const sim::Footprint short_fp{0.10, 0.7, 0};
	const sim::CollisionWorld cw(w, short_fp);
	const Eigen::Vector3d from(0.9, 0, 0), to(1.1, 0, 0);
	ASSERT_FALSE(cw.touchAt(from));
	ASSERT_FALSE(cw.touchAt(to));  // both ends free: only the motion in between hits the sheet
	Rig rig(w, from, short_fp);
	rig.drive(1);
	ASSERT_TRUE(rig.base.lastContact());
	EXPECT_EQ(rig.base.lastContact()->what, "obstacle.sheet");
	EXPECT_NEAR(rig.base.truePose()[0], 0.975 - 0.05, 2e-3);
}

TEST(Collisions, AFortyFiveDegreeTurnCannotJumpAThinPost)
{
	// a 5 cm post on the circle the front-left corner sweeps, between its start and end angles
	const double r = 0.51, a = 63 * M_PI / 180;
	const auto w = roomWith("[obstacle.post]\ncentre_m = " + std::to_string(r * std::sin(a)) + " " +
	                        std::to_string(r * std::cos(a)) + "\nsize_m = 0.05 1.0 0.05\n");
	const sim::CollisionWorld cw(w, {});
	const Eigen::Vector3d from(0, 0, 0), to(0, 0, M_PI / 4);
	ASSERT_FALSE(cw.touchAt(from));
	ASSERT_FALSE(cw.touchAt(to));
	const auto c = cw.firstContact(from, to);
	ASSERT_TRUE(c);
	EXPECT_EQ(c->what, "obstacle.post");
	EXPECT_GT(c->free_fraction, 0.0);
	EXPECT_LT(c->free_fraction, 1.0);
	EXPECT_FALSE(cw.touchAt(c->last_free_zxphi));
}

TEST(Collisions, TheBumperStaysPressedAgainstAWallAndReleasesWhenTheBaseBacksAway)
{
	Rig rig(roomWith(), {4.05, 0, 0});
	rig.drive(12);
	ASSERT_TRUE(rig.base.odometry().bumper);
	const Eigen::Vector3d against = rig.base.truePose();
	rig.base.step({0, 0, 1.0});  // standing still
	EXPECT_TRUE(rig.base.odometry().bumper);
	const int contacts = rig.base.contactsSoFar();
	rig.drive(1);  // pushing on: no motion, still pressed
	EXPECT_TRUE(rig.base.odometry().bumper);
	EXPECT_NEAR((rig.base.truePose() - against).norm(), 0, 1e-3);
	EXPECT_EQ(rig.base.contactsSoFar(), contacts + 1);
	rig.drive(1, -0.2);
	EXPECT_FALSE(rig.base.odometry().bumper);
	EXPECT_NEAR(rig.base.truePose()[0], against[0] - 0.2, 1e-6);
	EXPECT_TRUE(rig.base.lastContact());  // the report keeps the latest contact
}

TEST(Collisions, ABaseStartingInsideSomethingIsRefused)
{
	const auto w = roomWith("[obstacle.crate]\ncentre_m = 0 0.3\nsize_m = 0.6 0.5 0.6\n");
	sim::SimBase b{base::LabmateModel(), sim::SimBaseOptions()};
	try
	{
		b.setCollisionWorld(std::make_shared<sim::CollisionWorld>(w, sim::Footprint{}));
		FAIL() << "no error";
	}
	catch (const std::invalid_argument& e)
	{
		EXPECT_NE(std::string(e.what()).find("obstacle.crate"), std::string::npos) << e.what();
	}
}
