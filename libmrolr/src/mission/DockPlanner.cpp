// Docking poses in front of the table's sides, the object ahead of the arm's column.
#include <mrolr/geometry/Frames.h>
#include <mrolr/mission/DockPlanner.h>
#include <mrolr/mission/Navigator.h>
#include <mrolr/util/OptionsBinder.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <ostream>

namespace mrolr::mission
{
namespace
{
/** (z, x) of a point of W. */
Eigen::Vector2d zx(const Eigen::Vector3d& p)
{
	return {p.z(), p.x()};
}

/** The arm's column (A's origin) in W, (z, x), for the base at @p xv. */
Eigen::Vector2d columnAt(const Eigen::Vector3d& xv, const Eigen::Isometry3d& T_C0inA_mm,
                         double head_height_m)
{
	const Eigen::Vector3d p_AinC0_m = T_C0inA_mm.inverse().translation() / 1000.0;
	return zx(geometry::T_C0inW(xv, head_height_m) * p_AinC0_m);
}

double travel(const std::vector<PlanTable>& tables, const Eigen::Vector2d& from,
              const Eigen::Vector2d& to, double clearance_m)
{
	double len = 0;
	Eigen::Vector2d prev = from;
	for (const auto& v : detourAroundTables(tables, from, to, clearance_m))
		len += (v - prev).norm(), prev = v;
	return len + (to - prev).norm();
}

/** One side of a table: outward normal and tangent in (z, x), distance of the side from the
 * table's centre. */
struct Side
{
	Eigen::Vector2d normal, tangent;
	double half = 0;    ///< the side from the centre
	double length = 0;  ///< the side's length
	std::string name;
};

std::vector<Side> sidesOf(const PlanTable& t)
{
	const double yaw = t.yaw_deg * M_PI / 180.0;
	const Eigen::Vector2d axis_z{std::cos(yaw), std::sin(yaw)}, axis_x{-std::sin(yaw), std::cos(yaw)};
	const std::string n = "table." + t.name + " ";
	return {{-axis_z, axis_x, 0.5 * t.depth_m, t.length_m, n + "-z side"},
	        {axis_z, axis_x, 0.5 * t.depth_m, t.length_m, n + "+z side"},
	        {-axis_x, axis_z, 0.5 * t.length_m, t.depth_m, n + "-x side"},
	        {axis_x, axis_z, 0.5 * t.length_m, t.depth_m, n + "+x side"}};
}
}  // namespace

namespace
{
using D = DockingOptions;
constexpr auto kOpt = util::Presence::Optional;  // docking was added after the mission files

const util::OptionsBinder<D>& dockingBinder()
{
	static const auto b = util::OptionsBinder<D>()
	                          .flag("drive_to_reach", &D::drive_to_reach, kOpt)
	                          .number("standoff_m", &D::standoff_m, 0.05, 5, kOpt)
	                          .number("lateral_step_m", &D::lateral_step_m, 0.01, 2, kOpt)
	                          .integer("lateral_steps", &D::lateral_steps, 0, 20, kOpt);
	return b;
}
}  // namespace

void DockingOptions::loadFromConfigFile(const mrpt::config::CConfigFileBase& c,
                                        const std::string& s)
{
	dockingBinder().load(c, s, *this);
}

void DockingOptions::dump(std::ostream& out) const
{
	dockingBinder().dump(out, *this);
}

const PlanTable* tableUnder(const std::vector<PlanTable>& tables, const Eigen::Vector3d& p_OinW_m)
{
	const PlanTable* best = nullptr;
	double best_d = std::numeric_limits<double>::infinity();
	for (const auto& t : tables)
		if (const double d = distanceToTables({t}, zx(p_OinW_m)); d < best_d)
			best_d = d, best = &t;
	return best;
}

std::vector<DockCandidate> dockCandidates(const std::vector<PlanTable>& tables,
                                          const PlanTable& table, const Eigen::Vector3d& p_OinW_m,
                                          const Eigen::Vector3d& from_zxphi,
                                          const Eigen::Isometry3d& T_C0inA_mm,
                                          double head_height_m, double clearance_m,
                                          const DockingOptions& o)
{
	const Eigen::Vector2d centre{table.z_m, table.x_m}, p_O = zx(p_OinW_m);
	std::vector<DockCandidate> out;
	for (const auto& side : sidesOf(table))
	{
		const Eigen::Vector2d facing = -side.normal;
		const double phi = std::atan2(facing.y(), facing.x());
		const Eigen::Vector2d on_side = centre + side.normal * (side.half + o.standoff_m);
		const double s_obj = (p_O - centre).dot(side.tangent);
		auto baseAt = [&](double s)
		{
			const Eigen::Vector2d c = on_side + side.tangent * s;
			return Eigen::Vector3d(c.x(), c.y(), phi);
		};
		// shift the base so that the column, not the head, lies on the object's line
		const double s_col = (columnAt(baseAt(s_obj), T_C0inA_mm, head_height_m) - centre)
		                         .dot(side.tangent);
		const double s0 = 2 * s_obj - s_col;
		for (int k = -o.lateral_steps; k <= o.lateral_steps; ++k)
		{
			const double along = s0 + k * o.lateral_step_m;
			if (std::abs(along) > 0.5 * side.length) continue;  // facing past the table's end
			const Eigen::Vector3d xv = baseAt(along);
			if (distanceToTables(tables, xv.head<2>()) < o.standoff_m - 1e-6) continue;
			DockCandidate c;
			c.pose = {"dock", xv};
			c.side = side.name;
			c.lateral_m = k * o.lateral_step_m;
			c.travel_m = travel(tables, from_zxphi.head<2>(), xv.head<2>(), clearance_m);
			out.push_back(c);
		}
	}
	// sides nearest first (the travel to their nearest candidate), and on a side the candidates
	// nearest the object's line first: they leave the arm the most margin
	std::map<std::string, double> side_travel;
	for (const auto& c : out)
		if (auto [it, fresh] = side_travel.emplace(c.side, c.travel_m); !fresh)
			it->second = std::min(it->second, c.travel_m);
	std::stable_sort(out.begin(), out.end(),
	                 [&](const DockCandidate& a, const DockCandidate& b)
	                 {
		                 const double ta = side_travel[a.side], tb = side_travel[b.side];
		                 if (ta != tb) return ta < tb;
		                 return std::abs(a.lateral_m) < std::abs(b.lateral_m) - 1e-9;
	                 });
	return out;
}

}  // namespace mrolr::mission
