// Going round a table: the detour keeps its clearance and is only taken when needed.
#include <mrolr/mission/Navigator.h>

#include <gtest/gtest.h>

using namespace mrolr;

namespace
{
std::vector<mission::PlanTable> tableWorld(double yaw_deg)
{
	return {mission::PlanTable{"main", 0.0, 1.5, yaw_deg, 1.6, 0.9, 0.75}};
}

/** Smallest distance (m) from points sampled along the polyline to the table's centre box, in
 * units where a point inside the grown footprint gives a negative value. */
double minClearance(const mission::PlanTable& t, const std::vector<Eigen::Vector2d>& poly)
{
	const double yaw = t.yaw_deg * M_PI / 180;
	const Eigen::Vector2d az(std::cos(yaw), std::sin(yaw)), ax(-std::sin(yaw), std::cos(yaw));
	double best = 1e9;
	for (size_t i = 1; i < poly.size(); ++i)
		for (int k = 0; k <= 200; ++k)
		{
			const Eigen::Vector2d p = poly[i - 1] + (poly[i] - poly[i - 1]) * (k / 200.0);
			const Eigen::Vector2d d = p - Eigen::Vector2d(t.z_m, t.x_m);
			const double dz = std::abs(d.dot(az)) - 0.5 * t.depth_m;
			const double dx = std::abs(d.dot(ax)) - 0.5 * t.length_m;
			best = std::min(best, std::max(dz, dx));
		}
	return best;
}
}  // namespace

TEST(TableDetour, StraightPathThroughTheTableGoesRoundIt)
{
	for (double yaw : {0.0, 30.0, -60.0})
	{
		const auto w = tableWorld(yaw);
		const Eigen::Vector2d from(-0.5, 0.1), to(3.5, -0.2);
		const auto via = mission::detourAroundTables(w, from, to, 0.4);
		ASSERT_FALSE(via.empty()) << yaw;
		std::vector<Eigen::Vector2d> poly{from};
		poly.insert(poly.end(), via.begin(), via.end());
		poly.push_back(to);
		EXPECT_GE(minClearance(w[0], poly), 0.4 - 1e-9) << yaw;
		EXPECT_LT(minClearance(w[0], {from, to}), 0) << "the straight path hit the table";
	}
}

TEST(TableDetour, ClearPathIsKept)
{
	const auto w = tableWorld(0);
	EXPECT_TRUE(mission::detourAroundTables(w, {0.0, 0.0}, {0.5, 0.0}, 0.45).empty());
	EXPECT_TRUE(mission::detourAroundTables(w, {0.5, 1.5}, {2.5, 1.5}, 0.3).empty());
}
