// Docking poses: they face the table from the standoff, put the object ahead of the arm's column,
// keep off other tables and come nearest first.
#include <mrolr/geometry/Frames.h>
#include <mrolr/mission/DockPlanner.h>

#include <gtest/gtest.h>

using namespace mrolr;

namespace
{
/** The shipped mount: the column 0.38 m ahead of C0, 0.1 m to its right, 0.711 m below. */
Eigen::Isometry3d shippedMount()
{
	Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
	T.linear() << 0, 0, 1, 1, 0, 0, 0, 1, 0;
	T.translation() = Eigen::Vector3d(-380, 100, 711);
	return T;
}

/** Distance of (z, x) point @p p from the table's top rectangle (0 inside). */
double toTable(const mission::PlanTable& t, const Eigen::Vector2d& p)
{
	const double yaw = t.yaw_deg * M_PI / 180;
	const Eigen::Vector2d az(std::cos(yaw), std::sin(yaw)), ax(-std::sin(yaw), std::cos(yaw));
	const Eigen::Vector2d d = p - Eigen::Vector2d(t.z_m, t.x_m);
	return std::hypot(std::max(std::abs(d.dot(az)) - 0.5 * t.depth_m, 0.0),
	                  std::max(std::abs(d.dot(ax)) - 0.5 * t.length_m, 0.0));
}

Eigen::Vector2d columnOf(const Eigen::Vector3d& xv)
{
	const Eigen::Vector3d p =
	    geometry::T_C0inW(xv, 1.0) * (shippedMount().inverse().translation() / 1000.0);
	return {p.z(), p.x()};
}
}  // namespace

TEST(DockPlanner, CandidatesFaceTheTableFromTheStandoffWithTheObjectAheadOfTheColumn)
{
	for (double yaw : {0.0, 35.0, -75.0})
	{
		const mission::PlanTable table{"main", 0.3, 1.5, yaw, 1.6, 0.9, 0.75};
		const Eigen::Vector3d p_OinW(0.5, 0.8, 1.9);  // near a corner, on the top
		mission::DockingOptions o;
		const auto c = mission::dockCandidates({table}, table, p_OinW, {0, 0, 0}, shippedMount(),
		                                       1.0, 0.45, o);
		ASSERT_GE(c.size(), 4u) << "yaw " << yaw;
		int on_line = 0;
		for (const auto& d : c)
		{
			const Eigen::Vector3d& xv = d.pose.xv_zxphi;
			EXPECT_NEAR(toTable(table, xv.head<2>()), o.standoff_m, 1e-6) << d.side;
			// looking ahead from the pose, the table is met at the standoff
			const Eigen::Vector2d ahead(std::cos(xv[2]), std::sin(xv[2]));
			EXPECT_LT(toTable(table, xv.head<2>() + ahead * (o.standoff_m + 0.01)), 0.011)
			    << d.side << ", yaw " << yaw;
			if (d.lateral_m != 0) continue;
			++on_line;
			// the object lies on the line through the column along the heading
			const Eigen::Vector2d to_obj = Eigen::Vector2d(p_OinW.z(), p_OinW.x()) - columnOf(xv);
			EXPECT_NEAR(to_obj.x() * ahead.y() - to_obj.y() * ahead.x(), 0, 1e-6) << d.side;
			EXPECT_GT(to_obj.dot(ahead), 0) << d.side;
		}
		EXPECT_GE(on_line, 3) << "a candidate on the object's line per side in front of it, yaw "
		                      << yaw;
		// by side, and on a side nearest the object's line first
		for (size_t i = 1; i < c.size(); ++i)
			if (c[i].side == c[i - 1].side)
			{
				EXPECT_LE(std::abs(c[i - 1].lateral_m), std::abs(c[i].lateral_m) + 1e-9);
			}
	}
}

TEST(DockPlanner, TheNearestSideComesFirstAndTheFarSideCostsTheWayRound)
{
	const mission::PlanTable table{"main", 0.0, 1.5, 0, 1.6, 0.9, 0.75};
	const auto c = mission::dockCandidates({table}, table, {0.2, 0.8, 1.72}, {0.5, 0, 0},
	                                       shippedMount(), 1.0, 0.45, {});
	ASSERT_FALSE(c.empty());
	EXPECT_EQ(c.front().side, "table.main -z side");  // the robot stands at its -z side
	for (const auto& d : c)
		if (d.side == "table.main +z side" && d.lateral_m == 0)
		{  // behind the table: at least round its end, never straight through
			const double straight = (d.pose.xv_zxphi.head<2>() - Eigen::Vector2d(0.5, 0)).norm();
			EXPECT_GT(d.travel_m, straight + 0.3);
		}
}

TEST(DockPlanner, CandidatesTooNearAnotherTableAreDropped)
{
	const mission::PlanTable table{"main", 0.0, 1.5, 0, 1.6, 0.9, 0.75};
	// a second table 0.4 m behind the first: nothing fits between them
	const mission::PlanTable behind{"back", 0.0, 2.8, 0, 1.6, 0.9, 0.75};
	mission::DockingOptions o;
	const auto c = mission::dockCandidates({table, behind}, table, {0.2, 0.8, 1.72}, {0.5, 0, 0},
	                                       shippedMount(), 1.0, 0.45, o);
	ASSERT_FALSE(c.empty());
	for (const auto& d : c)
	{
		EXPECT_NE(d.side, "table.main +z side");
		EXPECT_GE(toTable(behind, d.pose.xv_zxphi.head<2>()), o.standoff_m - 1e-6);
	}
}

TEST(DockPlanner, TheTableUnderAnObjectIsTheNearestFootprint)
{
	const std::vector<mission::PlanTable> tables{{"a", 0.0, 1.5, 0, 1.6, 0.9, 0.75},
	                                             {"b", -3.0, 1.6, -75, 1.6, 0.9, 0.7}};
	EXPECT_EQ(mission::tableUnder(tables, {0.7, 0.8, 1.2})->name, "a");
	EXPECT_EQ(mission::tableUnder(tables, {-2.8, 0.7, 1.3})->name, "b");
	EXPECT_EQ(mission::tableUnder({}, {0, 0, 0}), nullptr);
}
