#include <mrolr/sim/Collisions.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace mrolr::sim
{
namespace
{
using Polygon = CollisionWorld::Polygon;

/** Overlaps smaller than this (m², 1 mm × 0.1 mm) are touching, not overlapping. */
constexpr double kMinOverlapArea_m2 = 1e-10;

double cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b) { return a[0] * b[1] - a[1] * b[0]; }

/** The part of convex @p poly where n·p ≤ c (Sutherland–Hodgman, one plane). */
Polygon clip(const Polygon& poly, const Eigen::Vector2d& n, double c)
{
	Polygon out;
	for (size_t i = 0; i < poly.size(); ++i)
	{
		const Eigen::Vector2d& a = poly[i];
		const Eigen::Vector2d& b = poly[(i + 1) % poly.size()];
		const double da = n.dot(a) - c, db = n.dot(b) - c;
		if (da <= 0) out.push_back(a);
		if ((da < 0 && db > 0) || (da > 0 && db < 0)) out.push_back(a + (b - a) * (da / (da - db)));
	}
	return out;
}

/** The overlap of two convex counter-clockwise polygons. */
Polygon intersection(Polygon a, const Polygon& b)
{
	for (size_t i = 0; i < b.size() && !a.empty(); ++i)
	{
		const Eigen::Vector2d e = b[(i + 1) % b.size()] - b[i];
		const Eigen::Vector2d outward(e[1], -e[0]);  // right of a counter-clockwise edge
		a = clip(a, outward, outward.dot(b[i]));
	}
	return a;
}

double area(const Polygon& p)
{
	double s = 0;
	for (size_t i = 0; i < p.size(); ++i) s += cross(p[i], p[(i + 1) % p.size()]);
	return 0.5 * s;
}

Eigen::Vector2d centroid(const Polygon& p)
{
	Eigen::Vector2d c = Eigen::Vector2d::Zero();
	for (size_t i = 0; i < p.size(); ++i)
		c += (p[i] + p[(i + 1) % p.size()]) * cross(p[i], p[(i + 1) % p.size()]);
	return c / (6 * area(p));
}

/** The overlap as a Touch, or nullopt when it is only a touch of edges. */
std::optional<Touch> touchOf(const std::string& what, const Polygon& overlap)
{
	if (overlap.size() < 3 || area(overlap) <= kMinOverlapArea_m2) return std::nullopt;
	return Touch{what, centroid(overlap)};
}

double pointSegmentDistance(const Eigen::Vector2d& p, const Eigen::Vector2d& a,
                            const Eigen::Vector2d& b)
{
	const Eigen::Vector2d ab = b - a;
	const double t = std::clamp((p - a).dot(ab) / std::max(ab.squaredNorm(), 1e-300), 0.0, 1.0);
	return (a + t * ab - p).norm();
}

/** Gap between two disjoint convex polygons (their nearest points include a vertex of one). */
double polygonGap(const Polygon& a, const Polygon& b)
{
	double d = std::numeric_limits<double>::infinity();
	for (const auto& [p, q] : {std::pair{&a, &b}, std::pair{&b, &a}})
		for (const auto& v : *p)
			for (size_t i = 0; i < q->size(); ++i)
				d = std::min(d, pointSegmentDistance(v, (*q)[i], (*q)[(i + 1) % q->size()]));
	return d;
}

double rad(double deg) { return deg * M_PI / 180.0; }
}  // namespace

Polygon rectangleOnFloor(double z_m, double x_m, double yaw_rad, double along_x_m, double along_z_m)
{
	const Eigen::Vector2d c(z_m, x_m);
	const Eigen::Vector2d own_z(std::cos(yaw_rad), std::sin(yaw_rad));  // heading direction
	const Eigen::Vector2d own_x(-std::sin(yaw_rad), std::cos(yaw_rad));  // its left
	const Eigen::Vector2d hz = own_z * (along_z_m / 2), hx = own_x * (along_x_m / 2);
	return {c + hz - hx, c + hz + hx, c - hz + hx, c - hz - hx};  // counter-clockwise from above
}

CollisionWorld::CollisionWorld(const world::World& world, const Footprint& footprint)
    : footprint_(footprint), has_room_(world.has_room)
{
	if (!(footprint.length_m > 0) || !(footprint.width_m > 0))
		throw std::invalid_argument("CollisionWorld: the footprint's length and width must be > 0");
	room_min_zx_ = {world.room.min_m.z(), world.room.min_m.x()};
	room_max_zx_ = {world.room.max_m.z(), world.room.max_m.x()};
	for (const auto& t : world.tables)
		bodies_.push_back(
		    {"table." + t.name, rectangleOnFloor(t.z_m, t.x_m, rad(t.yaw_deg), t.length_m, t.depth_m)});
	for (const auto& o : world.obstacles)
		bodies_.push_back({"obstacle." + o.name, rectangleOnFloor(o.z_m, o.x_m, rad(o.yaw_deg),
		                                                          o.size_m.x(), o.size_m.z())});
}

Polygon CollisionWorld::footprintAt(const Eigen::Vector3d& pose_zxphi, double margin_m) const
{
	const double phi = pose_zxphi[2];
	const Eigen::Vector2d c = pose_zxphi.head<2>() +
	                          footprint_.offset_m * Eigen::Vector2d(std::cos(phi), std::sin(phi));
	return rectangleOnFloor(c[0], c[1], phi, footprint_.width_m + 2 * margin_m,
	                        footprint_.length_m + 2 * margin_m);
}

double CollisionWorld::footprintRadius() const
{
	return std::hypot(std::abs(footprint_.offset_m) + footprint_.length_m / 2,
	                  footprint_.width_m / 2);
}

std::optional<Touch> CollisionWorld::wallTouch(const Polygon& fp) const
{
	if (!has_room_) return std::nullopt;
	// the four half-planes beyond the walls: n·p ≤ c
	for (int axis : {0, 1})
	{
		Eigen::Vector2d n = Eigen::Vector2d::Zero();
		n[axis] = 1;
		if (auto t = touchOf("wall", clip(fp, -n, -room_max_zx_[axis]))) return t;
		if (auto t = touchOf("wall", clip(fp, n, room_min_zx_[axis]))) return t;
	}
	return std::nullopt;
}

double CollisionWorld::wallGap(const Polygon& fp) const
{
	double d = std::numeric_limits<double>::infinity();
	if (!has_room_) return d;
	for (const auto& p : fp)
		for (int axis : {0, 1})
			d = std::min({d, p[axis] - room_min_zx_[axis], room_max_zx_[axis] - p[axis]});
	return std::max(d, 0.0);
}

std::optional<Touch> CollisionWorld::touchAt(const Eigen::Vector3d& pose_zxphi,
                                             double margin_m) const
{
	const Polygon fp = footprintAt(pose_zxphi, margin_m);
	if (auto t = wallTouch(fp)) return t;
	for (const auto& b : bodies_)
		if (auto t = touchOf(b.what, intersection(fp, b.outline))) return t;
	return std::nullopt;
}

Clearance CollisionWorld::clearanceAt(const Eigen::Vector3d& pose_zxphi) const
{
	if (auto t = touchAt(pose_zxphi)) return {t->what, 0.0};
	const Polygon fp = footprintAt(pose_zxphi);
	Clearance c{has_room_ ? "wall" : "", wallGap(fp)};
	for (const auto& b : bodies_)
		if (const double d = polygonGap(fp, b.outline); d < c.distance_m) c = {b.what, d};
	if (c.what.empty()) c.distance_m = std::numeric_limits<double>::infinity();
	return c;
}

std::optional<Contact> CollisionWorld::firstContact(const Eigen::Vector3d& from,
                                                    const Eigen::Vector3d& to) const
{
	const Motion straight = [from, to](double t) -> Eigen::Vector3d { return from + t * (to - from); };
	return firstContact(straight, (to.head<2>() - from.head<2>()).norm(), std::abs(to[2] - from[2]));
}

std::optional<Contact> CollisionWorld::firstContact(const Motion& motion, double travel_m,
                                                    double turn_rad) const
{
	const Eigen::Vector3d start = motion(0);
	if (auto t = touchAt(start)) return Contact{t->what, t->p_zx_m, start, 0.0};
	// no footprint point moves faster than the axle centre plus radius × turn rate
	const double sweep_m = std::abs(travel_m) + footprintRadius() * std::abs(turn_rad);
	const int n = std::max(1, int(std::ceil(sweep_m / kSampleStep_m)));
	for (int i = 1; i <= n; ++i)
		if (touchAt(motion(double(i) / n))) return bisect(motion, double(i - 1) / n, double(i) / n, sweep_m);
	return std::nullopt;
}

Contact CollisionWorld::bisect(const Motion& motion, double t_free, double t_hit,
                               double sweep_m) const
{
	while (sweep_m * (t_hit - t_free) > kContactTolerance_m)
	{
		const double mid = 0.5 * (t_free + t_hit);
		(touchAt(motion(mid)) ? t_hit : t_free) = mid;
	}
	const Touch hit = *touchAt(motion(t_hit));
	return Contact{hit.what, hit.p_zx_m, motion(t_free), t_free};
}

}  // namespace mrolr::sim
