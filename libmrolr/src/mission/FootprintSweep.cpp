// The base's footprint swept along a planned leg against the plan's tables (separating axes).
#include <mrolr/mission/FootprintSweep.h>

#include <array>
#include <cmath>

namespace mrolr::mission
{
namespace
{
using Corners = std::array<Eigen::Vector2d, 4>;

/** Corners (z, x) of a rectangle centred at @p c, its first axis at @p yaw, half sizes @p h. */
Corners rectangle(const Eigen::Vector2d& c, double yaw, double half_along, double half_across)
{
	const Eigen::Vector2d a(std::cos(yaw), std::sin(yaw)), b(-std::sin(yaw), std::cos(yaw));
	return {c + half_along * a + half_across * b, c + half_along * a - half_across * b,
	        c - half_along * a - half_across * b, c - half_along * a + half_across * b};
}

/** A table's footprint: its depth along its own z (yaw from W's z), its length along its x. */
Corners tableCorners(const PlanTable& t, double margin_m)
{
	return rectangle({t.z_m, t.x_m}, t.yaw_deg * M_PI / 180.0, 0.5 * t.depth_m + margin_m,
	                 0.5 * t.length_m + margin_m);
}

/** Separating axis test of two convex quadrilaterals. */
bool overlap(const Corners& p, const Corners& q)
{
	for (const Corners* poly : {&p, &q})
		for (int i = 0; i < 4; ++i)
		{
			const Eigen::Vector2d e = (*poly)[(i + 1) % 4] - (*poly)[i];
			const Eigen::Vector2d n(-e.y(), e.x());
			double pmin = 1e18, pmax = -1e18, qmin = 1e18, qmax = -1e18;
			for (const auto& v : p) pmin = std::min(pmin, n.dot(v)), pmax = std::max(pmax, n.dot(v));
			for (const auto& v : q) qmin = std::min(qmin, n.dot(v)), qmax = std::max(qmax, n.dot(v));
			if (pmax < qmin || qmax < pmin) return false;
		}
	return true;
}

/** The poses a step passes through, sampled finely enough for the sweep. */
std::vector<Eigen::Vector3d> sweep(const Eigen::Vector3d& xv, const base::PlannedStep& s)
{
	const bool rotate = s.kind == base::PlannedStep::Kind::Rotate;
	const double per_sample = rotate ? M_PI / 180.0 : 0.02;
	const int n = std::max(1, static_cast<int>(std::ceil(std::abs(s.amount) / per_sample)));
	std::vector<Eigen::Vector3d> out;
	for (int k = 1; k <= n; ++k)
	{
		const double f = s.amount * k / n;
		out.push_back(rotate ? Eigen::Vector3d(xv.x(), xv.y(), xv.z() + f)
		                     : Eigen::Vector3d(xv.x() + f * std::cos(xv.z()),
		                                       xv.y() + f * std::sin(xv.z()), xv.z()));
	}
	return out;
}
}  // namespace

bool footprintTouchesTable(const std::vector<PlanTable>& tables, const base::LabmateOptions& base,
                           const Eigen::Vector3d& xv, double margin_m)
{
	const Corners robot = rectangle(xv.head<2>(), xv.z(), 0.5 * base.footprint_length_m,
	                                0.5 * base.footprint_width_m);
	for (const auto& t : tables)
		if (overlap(robot, tableCorners(t, margin_m))) return true;
	return false;
}

std::optional<size_t> firstBlockedStep(const std::vector<PlanTable>& tables,
                                       const base::LabmateOptions& base, Eigen::Vector3d xv,
                                       const std::vector<base::PlannedStep>& plan,
                                       double margin_m)
{
	for (size_t i = 0; i < plan.size(); ++i)
	{
		for (const auto& p : sweep(xv, plan[i]))
			if (footprintTouchesTable(tables, base, p, margin_m)) return i;
		xv = sweep(xv, plan[i]).back();
	}
	return std::nullopt;
}

}  // namespace mrolr::mission
