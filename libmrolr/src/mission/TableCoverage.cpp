// The views of a sweep that covers the table top, with tilt and vergence following it.
#include <mrolr/geometry/Frames.h>
#include <mrolr/mission/Navigator.h>
#include <mrolr/mission/TableCoverage.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>

namespace mrolr::mission
{
namespace
{
constexpr double kDeg = M_PI / 180.0;

/** The table's top in C0: its centre, own axes (x, z components of C0) and half sizes. */
struct TopInC0
{
	Eigen::Vector2d centre, axis_x, axis_z;  ///< (x, z) of C0
	double half_x = 0, half_z = 0, y_m = 0;  ///< y: the top's height in C0
};

TopInC0 topInC0(const PlanTable& t, const Eigen::Vector3d& xv, double head_height_m)
{
	const Eigen::Isometry3d T_WinC0 = geometry::T_C0inW(xv, head_height_m).inverse();
	const double yaw = t.yaw_deg * kDeg;
	// the table's own axes in W (x, y, z): its z at yaw from W's z towards x
	const Eigen::Vector3d ax_W(std::cos(yaw), 0, -std::sin(yaw)), az_W(std::sin(yaw), 0, std::cos(yaw));
	const Eigen::Vector3d c = T_WinC0 * Eigen::Vector3d(t.x_m, t.top_height_m, t.z_m);
	const Eigen::Vector3d ax = T_WinC0.linear() * ax_W, az = T_WinC0.linear() * az_W;
	return {{c.x(), c.z()}, {ax.x(), ax.z()}, {az.x(), az.z()}, 0.5 * t.length_m,
	        0.5 * t.depth_m, c.y()};
}

/** Where the ray from C0's origin at bearing @p pan_rad (from z towards x) enters and leaves the
 * top (slab method in the top's frame); false when it misses. */
bool rayThroughTop(const TopInC0& top, double pan_rad, double& t_in, double& t_out)
{
	const Eigen::Vector2d d(std::sin(pan_rad), std::cos(pan_rad));
	const Eigen::Vector2d o = -top.centre;  // C0's origin relative to the top's centre
	t_in = 0, t_out = std::numeric_limits<double>::infinity();
	for (const auto& [axis, half] : {std::pair{top.axis_x, top.half_x}, std::pair{top.axis_z, top.half_z}})
	{
		const double od = o.dot(axis), dd = d.dot(axis);
		if (std::abs(dd) < 1e-12)
		{
			if (std::abs(od) > half) return false;
			continue;
		}
		double a = (-half - od) / dd, b = (half - od) / dd;
		if (a > b) std::swap(a, b);
		t_in = std::max(t_in, a), t_out = std::min(t_out, b);
	}
	return t_out > t_in;
}

TableView viewAt(const TopInC0& top, double pan_deg)
{
	double t_in = 0, t_out = 0;
	double range = top.centre.norm();  // a bearing past the top: fixate as far as its centre
	if (rayThroughTop(top, pan_deg * kDeg, t_in, t_out)) range = 0.5 * (t_in + t_out);
	return {pan_deg, Eigen::Vector3d(range * std::sin(pan_deg * kDeg), top.y_m,
	                                 range * std::cos(pan_deg * kDeg))};
}
}  // namespace

const PlanTable* tableInFront(const std::vector<PlanTable>& tables, const Eigen::Vector3d& xv)
{
	const PlanTable* best = nullptr;
	double best_d = std::numeric_limits<double>::infinity();
	const Eigen::Vector2d ahead(std::cos(xv.z()), std::sin(xv.z()));
	for (const auto& t : tables)
	{
		const Eigen::Vector2d to_centre = Eigen::Vector2d(t.z_m, t.x_m) - xv.head<2>();
		if (to_centre.dot(ahead) <= 0) continue;
		if (const double d = distanceToTables({t}, xv.head<2>()); d < best_d) best_d = d, best = &t;
	}
	return best;
}

std::vector<TableView> tableViews(const PlanTable& table, const Eigen::Vector3d& xv_zxphi,
                                  double head_height_m, double half_fov_deg, double pan_step_deg)
{
	const TopInC0 top = topInC0(table, xv_zxphi, head_height_m);
	double lo = std::numeric_limits<double>::infinity(), hi = -lo;
	for (double sx : {-1.0, 1.0})
		for (double sz : {-1.0, 1.0})
		{
			const Eigen::Vector2d p = top.centre + sx * top.half_x * top.axis_x + sz * top.half_z * top.axis_z;
			if (p.y() <= 0) continue;  // behind the cameras
			const double b = std::atan2(p.x(), p.y()) / kDeg;
			lo = std::min(lo, b), hi = std::max(hi, b);
		}
	if (lo > hi) return {};
	double from = lo + half_fov_deg, to = hi - half_fov_deg;
	if (from > to) from = to = 0.5 * (lo + hi);
	std::vector<TableView> out;
	for (double pan = from; pan < to - 1e-6; pan += pan_step_deg) out.push_back(viewAt(top, pan));
	out.push_back(viewAt(top, to));  // the far end, whatever the step
	return out;
}

std::vector<TableView> betweenViews(const PlanTable& table, const Eigen::Vector3d& xv_zxphi,
                                    double head_height_m, const std::vector<TableView>& views)
{
	const TopInC0 top = topInC0(table, xv_zxphi, head_height_m);
	std::vector<TableView> out;
	for (size_t i = 1; i < views.size(); ++i)
		out.push_back(viewAt(top, 0.5 * (views[i - 1].pan_deg + views[i].pan_deg)));
	return out;
}

}  // namespace mrolr::mission
