// Going round a table that lies on a straight leg (the thesis's future work, 7.2.2).
#include <mrolr/mission/Navigator.h>

#include <cmath>
#include <limits>

namespace mrolr::mission
{
namespace
{
/** A table's footprint grown by the clearance, in its own frame (local z along its depth). */
struct Footprint
{
	Eigen::Vector2d centre;          ///< (z, x) in W
	Eigen::Vector2d axis_z, axis_x;  ///< table's z and x axes in (z, x) coordinates of W
	double half_z = 0, half_x = 0;

	Eigen::Vector2d toLocal(const Eigen::Vector2d& p) const
	{
		const Eigen::Vector2d d = p - centre;
		return {d.dot(axis_z), d.dot(axis_x)};
	}
	Eigen::Vector2d toWorld(const Eigen::Vector2d& l) const
	{
		return centre + l.x() * axis_z + l.y() * axis_x;
	}
	bool inside(const Eigen::Vector2d& p) const
	{
		const auto l = toLocal(p);
		return std::abs(l.x()) < half_z && std::abs(l.y()) < half_x;
	}
};

Footprint footprintOf(const PlanTable& t, double clearance_m)
{
	const double yaw = t.yaw_deg * M_PI / 180.0;
	Footprint f;
	f.centre = {t.z_m, t.x_m};
	f.axis_z = {std::cos(yaw), std::sin(yaw)};
	f.axis_x = {-std::sin(yaw), std::cos(yaw)};
	f.half_z = 0.5 * t.depth_m + clearance_m;
	f.half_x = 0.5 * t.length_m + clearance_m;
	return f;
}

/** True when the segment passes through the footprint (sampled every centimetre). */
bool crosses(const Footprint& f, const Eigen::Vector2d& a, const Eigen::Vector2d& b)
{
	const int n = std::max(2, static_cast<int>((b - a).norm() / 0.01));
	for (int i = 1; i < n; ++i)
		if (f.inside(a + (b - a) * (static_cast<double>(i) / n))) return true;
	return false;
}

double pathLength(const Eigen::Vector2d& a, const std::vector<Eigen::Vector2d>& via,
                  const Eigen::Vector2d& b)
{
	double len = 0;
	Eigen::Vector2d prev = a;
	for (const auto& v : via) len += (v - prev).norm(), prev = v;
	return len + (b - prev).norm();
}

/** Round the footprint on side @p s (+1: the table's +x side) through its corners, pushed out by
 * a centimetre so that the corner points themselves are clear. */
std::vector<Eigen::Vector2d> roundSide(const Footprint& f, const Eigen::Vector2d& a,
                                       const Eigen::Vector2d& b, double s)
{
	const double za = f.toLocal(a).x() < 0 ? -1 : 1, zb = f.toLocal(b).x() < 0 ? -1 : 1;
	const double hz = f.half_z + 0.01, hx = f.half_x + 0.01;
	std::vector<Eigen::Vector2d> via{f.toWorld({za * hz, s * hx})};
	if (zb != za) via.push_back(f.toWorld({zb * hz, s * hx}));
	return via;
}

bool clear(const Footprint& f, const Eigen::Vector2d& a, const std::vector<Eigen::Vector2d>& via,
           const Eigen::Vector2d& b)
{
	Eigen::Vector2d prev = a;
	for (const auto& v : via)
	{
		if (crosses(f, prev, v)) return false;
		prev = v;
	}
	return !crosses(f, prev, b);
}
}  // namespace

std::vector<Eigen::Vector2d> detourAroundTables(const std::vector<PlanTable>& tables,
                                                const Eigen::Vector2d& from,
                                                const Eigen::Vector2d& to, double clearance_m)
{
	for (const auto& t : tables)
	{
		const auto f = footprintOf(t, clearance_m);
		if (f.inside(from) || f.inside(to) || !crosses(f, from, to)) continue;
		std::vector<Eigen::Vector2d> best;
		double best_len = std::numeric_limits<double>::infinity();
		for (double s : {1.0, -1.0})
		{
			auto via = roundSide(f, from, to, s);
			const double len = pathLength(from, via, to);
			if (clear(f, from, via, to) && len < best_len) best = via, best_len = len;
		}
		return best;
	}
	return {};
}

double distanceToTables(const std::vector<PlanTable>& tables, const Eigen::Vector2d& p_zx)
{
	double best = std::numeric_limits<double>::infinity();
	for (const auto& t : tables)
	{
		const Eigen::Vector2d l = footprintOf(t, 0).toLocal(p_zx);
		const double dz = std::max(std::abs(l.x()) - 0.5 * t.depth_m, 0.0);
		const double dx = std::max(std::abs(l.y()) - 0.5 * t.length_m, 0.0);
		best = std::min(best, std::hypot(dz, dx));
	}
	return best;
}

bool canTurnAt(const std::vector<PlanTable>& tables, const Eigen::Vector2d& p_zx,
               double turn_radius_m)
{
	return distanceToTables(tables, p_zx) >= turn_radius_m + kTurnMargin_m;
}

}  // namespace mrolr::mission
