// A station close to a table, reached from wherever the base happens to be near it: the base
// lines up with the station's heading where turning is clear and drives straight in; it never
// sweeps a corner into the table on the way.
#include "MissionTestConfig.h"

#include <mrolr/mission/Navigator.h>
#include <mrolr/sim/Collisions.h>
#include <mrolr/sim/SimBase.h>

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <sstream>

using namespace mrolr;

namespace
{
constexpr double kDeg = M_PI / 180;

/** A room with one table (centre z 1.5, x 0, yaw @p yaw_deg, 1.6 × 0.9 m). */
world::World tableRoom(double yaw_deg)
{
	return world::World::parse("[room]\nmin_m = -4 0 -3\nmax_m = 4 3 7\n[waypoints]\nW0 = 0 0 0\n"
	                           "[table.main]\ncentre_m = 0 1.5\nyaw_deg = " +
	                           std::to_string(yaw_deg) + "\nsize_m = 1.6 0.9 0.75\n");
}

/** The pose @p off_m beyond the table's far side, on its axis, facing the table. */
Eigen::Vector3d facingTheFarSide(double yaw_deg, double off_m)
{
	const double yaw = yaw_deg * kDeg;
	const Eigen::Vector2d centre(1.5, 0.0), axis(std::cos(yaw), std::sin(yaw));
	const Eigen::Vector2d p = centre + (0.45 + off_m) * axis;
	return {p.x(), p.y(), yaw + M_PI};
}
}  // namespace

TEST(TableApproach, AStationTightAgainstATableIsReachedFromAskewStartsWithoutTouchingIt)
{
	for (double yaw : {0.0, 35.0, -70.0})
		for (const auto& [off_m, lateral_m, heading_deg] : std::vector<std::array<double, 3>>{
		         {0.85, -0.3, 80}, {0.85, 0.25, -100}, {0.73, -0.26, -99}, {0.7, 0.3, 60},
		         {0.65, -0.2, 150}, {0.85, 0.0, 0}})
		{
			// the station: the footprint's front 0.1 m from the table's edge (front 0.4 m ahead)
			const Eigen::Vector3d station = facingTheFarSide(yaw, 0.5);
			const Eigen::Vector3d beyond = facingTheFarSide(yaw, off_m);
			const Eigen::Vector2d side(-std::sin(station.z()), std::cos(station.z()));
			const Eigen::Vector2d s = beyond.head<2>() + lateral_m * side;
			const Eigen::Vector3d start(s.x(), s.y(), station.z() + heading_deg * kDeg);
			std::ostringstream where;
			where << "table yaw " << yaw << " deg, start " << start.transpose();

			auto cfg = mission::test::defaultMissionConfig();
			cfg.write("mission", "mode", "dead_reckoning");
			std::ostringstream w0;
			w0 << start.x() << " " << start.y() << " " << start.z() / kDeg;
			auto o = mission::test::optionsFrom(
			    cfg, mission::test::planWith({{"plan", "route", "W0"}, {"waypoints", "W0", w0.str()}}));
			o.plan.tables = {mission::PlanTable{"main", 0.0, 1.5, yaw, 1.6, 0.9, 0.75}};

			base::LabmateOptions noiseless = o.labmate;
			noiseless.velocity_noise_fraction = 0;
			const base::LabmateModel model(noiseless);
			sim::SimBaseOptions slip_free;
			slip_free.slip_probability = 0;  // dead reckoning: the estimate is the truth
			sim::SimBase base(model, slip_free, start);
			sim::Footprint fp;
			fp.length_m = o.labmate.footprint_length_m, fp.width_m = o.labmate.footprint_width_m;
			base.setCollisionWorld(std::make_shared<sim::CollisionWorld>(tableRoom(yaw), fp));

			mission::Timeline timeline;
			mission::Navigator nav(o, base, timeline);
			nav.driveTo({"S", station});
			EXPECT_EQ(base.contactsSoFar(), 0) << where.str();
			EXPECT_FALSE(base.lastContact().has_value()) << where.str();
			EXPECT_LT((base.truePose().head<2>() - station.head<2>()).norm(),
			          o.navigation.waypoint_tolerance_m + 0.02)
			    << where.str() << ": ended at " << base.truePose().transpose();
		}
}
