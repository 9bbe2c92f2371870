// Limbs of bodies of revolution (Limbs.h): coaxial circles grouped into a profile, and the two
// outline generators of each cylinder or cone frustum between consecutive levels.
#include <mrolr/recog/images/Limbs.h>

#include <algorithm>
#include <cmath>

namespace mrolr::recog
{
namespace
{
struct Circle
{
	Eigen::Vector3d c, n;
	double r = 0;
};

std::vector<Circle> circlesOf(const std::vector<Feature>& fs, const RevolutionGrouping& g)
{
	std::vector<Circle> out;
	for (const auto& f : fs)
	{
		if (f.isLine() || f.a_mm <= 0 || f.b_mm <= 0) continue;
		const double r = 0.5 * (f.a_mm + f.b_mm);
		if (std::min(f.a_mm, f.b_mm) < g.min_roundness * std::max(f.a_mm, f.b_mm)) continue;
		if (f.len_mm < g.min_arc_fraction * 2 * M_PI * r) continue;
		out.push_back({f.m, f.u.normalized(), r});
	}
	return out;
}

bool onAxis(const Circle& c, const Eigen::Vector3d& a, const Eigen::Vector3d& d,
            const RevolutionGrouping& g)
{
	if (std::abs(c.n.dot(d)) < std::cos(g.max_tilt_deg * M_PI / 180)) return false;
	const Eigen::Vector3d v = c.c - a;
	return (v - v.dot(d) * d).norm() <= g.max_offset_frac * c.r;
}

std::vector<size_t> members(const std::vector<Circle>& cs, const std::vector<bool>& used,
                            const Eigen::Vector3d& a, const Eigen::Vector3d& d,
                            const RevolutionGrouping& g)
{
	std::vector<size_t> out;
	for (size_t i = 0; i < cs.size(); ++i)
		if (!used[i] && onAxis(cs[i], a, d, g)) out.push_back(i);
	return out;
}

struct Level
{
	double z_mm, r_mm;
};

/** Levels along the axis (circles within merge_mm of the next one, chained, are one level), then
 * one frustum between each two consecutive levels, from their circles of most similar radius
 * (the larger pair on a tie). */
std::vector<ProfileSegment> profileOf(std::vector<Level> pts, double merge_mm)
{
	std::sort(pts.begin(), pts.end(),
	          [](const Level& a, const Level& b) { return a.z_mm < b.z_mm; });
	std::vector<std::vector<Level>> levels;
	for (size_t i = 0; i < pts.size(); ++i)
	{
		if (i == 0 || pts[i].z_mm - pts[i - 1].z_mm > merge_mm) levels.emplace_back();
		levels.back().push_back(pts[i]);
	}
	std::vector<ProfileSegment> out;
	for (size_t k = 0; k + 1 < levels.size(); ++k)
	{
		const Level *best_a = nullptr, *best_b = nullptr;
		for (const auto& a : levels[k])
			for (const auto& b : levels[k + 1])
			{
				if (!best_a)
				{
					best_a = &a, best_b = &b;
					continue;
				}
				const double d = std::abs(a.r_mm - b.r_mm),
				             best = std::abs(best_a->r_mm - best_b->r_mm);
				if (d < best - 1e-9 ||
				    (d < best + 1e-9 && a.r_mm + b.r_mm > best_a->r_mm + best_b->r_mm))
					best_a = &a, best_b = &b;
			}
		out.push_back({best_a->z_mm, best_a->r_mm, best_b->z_mm, best_b->r_mm});
	}
	return out;
}
}  // namespace

std::vector<RevolutionBody> revolutionBodiesOf(const std::vector<Feature>& features_O,
                                               const RevolutionGrouping& g)
{
	const auto cs = circlesOf(features_O, g);
	std::vector<size_t> order(cs.size());
	for (size_t i = 0; i < cs.size(); ++i) order[i] = i;
	std::sort(order.begin(), order.end(), [&](size_t a, size_t b) { return cs[a].r > cs[b].r; });
	std::vector<bool> used(cs.size(), false);
	std::vector<RevolutionBody> bodies;
	for (const size_t seed : order)
	{
		if (used[seed]) continue;
		auto in = members(cs, used, cs[seed].c, cs[seed].n, g);
		if (in.size() < 2) continue;
		// the axis refitted on the group: mean of the sign-aligned normals and of the centres
		Eigen::Vector3d d = Eigen::Vector3d::Zero(), a = Eigen::Vector3d::Zero();
		for (const size_t i : in)
			d += cs[i].n.dot(cs[seed].n) < 0 ? -cs[i].n : cs[i].n, a += cs[i].c;
		d.normalize(), a /= static_cast<double>(in.size());
		in = members(cs, used, a, d, g);
		std::vector<Level> pts;
		for (const size_t i : in) pts.push_back({(cs[i].c - a).dot(d), cs[i].r});
		RevolutionBody b{a, d, profileOf(pts, g.level_merge_mm)};
		if (b.profile.empty() || b.profile.back().z1_mm - b.profile.front().z0_mm < g.min_length_mm)
			continue;
		for (const size_t i : in) used[i] = true;
		bodies.push_back(std::move(b));
	}
	return bodies;
}

std::vector<std::pair<Eigen::Vector3d, Eigen::Vector3d>> limbLines(const RevolutionBody& body,
                                                                   const Eigen::Vector3d& c_O)
{
	std::vector<std::pair<Eigen::Vector3d, Eigen::Vector3d>> out;
	const Eigen::Vector3d& d = body.axis_dir;
	const Eigen::Vector3d e1 = d.unitOrthogonal(), e2 = d.cross(e1);
	const Eigen::Vector3d v = c_O - body.axis_point;
	const double cz = v.dot(d), cx = v.dot(e1), cy = v.dot(e2);
	const double rho = std::hypot(cx, cy), psi = std::atan2(cy, cx);
	for (const auto& s : body.profile)
	{
		const double k = (s.r1_mm - s.r0_mm) / (s.z1_mm - s.z0_mm);
		// the generator at angle phi has the tangent plane n = u(phi) - k d along its whole
		// length; it is on the outline where that plane holds the camera:
		// cx cos(phi) + cy sin(phi) = r0 - k (z0 - cz)
		const double q = s.r0_mm - k * (s.z0_mm - cz);
		if (rho <= std::abs(q) || s.r0_mm + s.r1_mm <= 0) continue;
		const double half = std::acos(q / rho);
		for (const double phi : {psi + half, psi - half})
		{
			const Eigen::Vector3d u = std::cos(phi) * e1 + std::sin(phi) * e2;
			out.emplace_back(body.axis_point + s.z0_mm * d + s.r0_mm * u,
			                 body.axis_point + s.z1_mm * d + s.r1_mm * u);
		}
	}
	return out;
}

std::vector<EdgeSample> limbSamples(const RevolutionBody& body, const Eigen::Vector3d& c_O,
                                    double spacing_mm)
{
	std::vector<EdgeSample> out;
	appendLimbSamples(body, c_O, spacing_mm, out);
	return out;
}

void appendLimbSamples(const RevolutionBody& body, const Eigen::Vector3d& c_O, double spacing_mm,
                       std::vector<EdgeSample>& out)
{
	for (const auto& [a, b] : limbLines(body, c_O))
	{
		const double len = (b - a).norm();
		const int n = std::max(2, static_cast<int>(std::ceil(len / spacing_mm)));
		const Eigen::Vector3d t = (b - a) / len;
		for (int i = 0; i < n; ++i) out.push_back({a + (b - a) * (i + 0.5) / n, t, -1});
	}
}

bool onSurface(const RevolutionBody& body, const Eigen::Vector3d& p_O, double tol_mm)
{
	const Eigen::Vector3d v = p_O - body.axis_point;
	const double z = v.dot(body.axis_dir), rho = (v - z * body.axis_dir).norm();
	for (const auto& s : body.profile)
	{
		if (z < s.z0_mm - tol_mm || z > s.z1_mm + tol_mm) continue;
		const double t = std::clamp((z - s.z0_mm) / (s.z1_mm - s.z0_mm), 0.0, 1.0);
		if (std::abs(rho - (s.r0_mm + t * (s.r1_mm - s.r0_mm))) <= tol_mm) return true;
	}
	return false;
}

namespace
{
/** Whether x(t) = c + t (p − c), t in [0, 1], enters the frustum shrunk by m: z0 <= z(t) <= z1
 * and rho(t) < R(t) = r0 + k (z(t) − z0) − m, i.e. rho² − R² < 0 with R > 0 (a quadratic in t). */
bool crossesFrustum(const ProfileSegment& s, double cz, double dz, const Eigen::Vector2d& w0,
                    const Eigen::Vector2d& w1, double m)
{
	double lo = 0, hi = 1;
	const auto clip = [&](double a, double b)  // keep the t with a + b t >= 0
	{
		if (std::abs(b) < 1e-12) return a >= 0;
		const double t = -a / b;
		if (b > 0)
			lo = std::max(lo, t);
		else
			hi = std::min(hi, t);
		return lo < hi;
	};
	const double k = (s.r1_mm - s.r0_mm) / (s.z1_mm - s.z0_mm);
	const double alpha = s.r0_mm - m + k * (cz - s.z0_mm), beta = k * dz;  // R(t)
	if (!clip(cz - s.z0_mm, dz) || !clip(s.z1_mm - cz, -dz) || !clip(alpha, beta)) return false;
	const double a = w1.squaredNorm() - beta * beta, b = 2 * w0.dot(w1) - 2 * alpha * beta,
	             c = w0.squaredNorm() - alpha * alpha;
	const auto f = [&](double t) { return (a * t + b) * t + c; };
	if (f(lo) < 0 || f(hi) < 0) return true;
	if (a <= 0) return false;
	const double tv = -b / (2 * a);
	return tv > lo && tv < hi && f(tv) < 0;
}
}  // namespace

BodySight bodySight(const RevolutionBody& body, const Eigen::Vector3d& c_O)
{
	const Eigen::Vector3d& d = body.axis_dir;
	BodySight s;
	s.c_O = c_O;
	s.e1 = d.unitOrthogonal(), s.e2 = d.cross(s.e1);
	const Eigen::Vector3d c = c_O - body.axis_point;
	s.w0 = Eigen::Vector2d(c.dot(s.e1), c.dot(s.e2));
	s.cz = c.dot(d);
	for (const auto& p : body.profile) s.r_max_mm = std::max({s.r_max_mm, p.r0_mm, p.r1_mm});
	return s;
}

bool crossesSolid(const RevolutionBody& body, const BodySight& sight, const Eigen::Vector3d& p_O,
                  double margin_mm)
{
	const Eigen::Vector3d v = p_O - sight.c_O;
	const Eigen::Vector2d w1(v.dot(sight.e1), v.dot(sight.e2));
	const double dz = v.dot(body.axis_dir);
	// a quick miss: the segment keeps farther from the axis than the widest shrunk frustum
	// reaches (with a margin far above rounding, so that the test below could only agree)
	const double ww = w1.squaredNorm();
	const double t = ww > 0 ? std::clamp(-sight.w0.dot(w1) / ww, 0.0, 1.0) : 0.0;
	const double reach = std::max(0.0, sight.r_max_mm - margin_mm) + 1e-6;
	if ((sight.w0 + t * w1).squaredNorm() > reach * reach) return false;
	for (const auto& s : body.profile)
		if (crossesFrustum(s, sight.cz, dz, sight.w0, w1, margin_mm)) return true;
	return false;
}

bool crossesSolid(const RevolutionBody& body, const Eigen::Vector3d& c_O,
                  const Eigen::Vector3d& p_O, double margin_mm)
{
	return crossesSolid(body, bodySight(body, c_O), p_O, margin_mm);
}

}  // namespace mrolr::recog
