#include <mrolr/model/ModelEditor.h>
#include <mrolr/model/WireFrameSampling.h>

#include <algorithm>
#include <cmath>

namespace mrolr::model
{
namespace
{
double distanceToInfiniteLine(const Eigen::Vector3d& p, const Line3& l)
{
	return (p - l.p1).cross(l.direction()).norm();
}

/** Two lines are one edge: parallel, each endpoint near the other's line, and overlapping or
 * nearly touching along it. */
bool sameLine(const Line3& a, const Line3& b, const MergeOptions& o)
{
	if (std::abs(a.direction().dot(b.direction())) < std::cos(o.max_angle_deg * M_PI / 180))
		return false;
	for (const auto* p : {&b.p1, &b.p2})
		if (distanceToInfiniteLine(*p, a) > o.max_distance_mm) return false;
	for (const auto* p : {&a.p1, &a.p2})
		if (distanceToInfiniteLine(*p, b) > o.max_distance_mm) return false;
	const Eigen::Vector3d d = a.direction();
	const double s1 = (b.p1 - a.p1).dot(d), s2 = (b.p2 - a.p1).dot(d);
	const double lo = std::min(s1, s2), hi = std::max(s1, s2);
	return lo <= a.length() + o.max_gap_mm && hi >= -o.max_gap_mm;
}

/** The line through both, length-weighted, spanning all four endpoints. */
Line3 joinLines(const Line3& a, const Line3& b)
{
	Eigen::Vector3d db = b.direction();
	if (db.dot(a.direction()) < 0) db = -db;
	const Eigen::Vector3d d = (a.length() * a.direction() + b.length() * db).normalized();
	const Eigen::Vector3d m = (a.length() * (a.p1 + a.p2) / 2 + b.length() * (b.p1 + b.p2) / 2) /
	                          (a.length() + b.length());
	double lo = 1e300, hi = -1e300;
	for (const auto* p : {&a.p1, &a.p2, &b.p1, &b.p2})
	{
		lo = std::min(lo, (*p - m).dot(d));
		hi = std::max(hi, (*p - m).dot(d));
	}
	return {a.length() >= b.length() ? a.id : b.id, m + lo * d, m + hi * d};
}

bool sameConic(const Conic3& a, const Conic3& b, const MergeOptions& o)
{
	return std::abs(a.normal.dot(b.normal)) >= std::cos(o.max_angle_deg * M_PI / 180) &&
	       (a.centre - b.centre).norm() <= o.max_centre_mm &&
	       std::abs(a.a - b.a) <= o.max_radius_diff_mm &&
	       std::abs(a.b - b.b) <= o.max_radius_diff_mm;
}

double parameterOn(const Conic3& c, const Eigen::Vector3d& p)
{
	const Eigen::Vector3d q = p - c.centre;
	return std::atan2(q.dot(c.normal.cross(c.major)) / c.b, q.dot(c.major) / c.a);
}

/** 2πk shift of @p x that is nearest to the interval [lo, hi]. */
double nearestTurn(double x, double lo, double hi)
{
	double best = x, best_d = 1e300;
	for (int k = -2; k <= 2; ++k)
	{
		const double y = x + 2 * M_PI * k, d = y < lo ? lo - y : (y > hi ? y - hi : 0);
		if (d < best_d) best_d = d, best = y;
	}
	return best;
}

/** Smallest arc of @p a's parametrisation covering a's arc and the points of b's arc. */
void unionArc(Conic3& a, const Conic3& b)
{
	double lo = a.t1, hi = a.t2, prev = 0;
	bool first = true;
	for (const auto& s : sampleConic(b, 2.0, 0))
	{
		double x = parameterOn(a, s.p);
		if (first) prev = x = nearestTurn(x, a.t1, a.t2), first = false;
		while (x - prev > M_PI) x -= 2 * M_PI;
		while (x - prev < -M_PI) x += 2 * M_PI;
		prev = x;
		lo = std::min(lo, x), hi = std::max(hi, x);
	}
	a.t1 = lo;
	a.t2 = std::min(hi, lo + 2 * M_PI);
}

Conic3 joinConics(const Conic3& a, const Conic3& b)
{
	const bool a_longer = arcLength(a) >= arcLength(b);
	Conic3 c = a_longer ? a : b;
	const Conic3& other = a_longer ? b : a;
	unionArc(c, other);
	return c;
}

/** One merge of the first duplicated pair found; false when there is none. */
template <typename T, typename Same, typename Join>
bool mergeOnce(std::vector<T>& v, Same same, Join join)
{
	for (size_t i = 0; i < v.size(); ++i)
		for (size_t j = i + 1; j < v.size(); ++j)
			if (same(v[i], v[j]))
			{
				v[i] = join(v[i], v[j]);
				v.erase(v.begin() + static_cast<long>(j));
				return true;
			}
	return false;
}
}  // namespace

bool isDuplicate(const Line3& a, const Line3& b, const MergeOptions& o)
{
	return sameLine(a, b, o);
}
bool isDuplicate(const Conic3& a, const Conic3& b, const MergeOptions& o)
{
	return sameConic(a, b, o);
}

size_t mergeDuplicates(WireFrame& wf, const MergeOptions& o)
{
	const size_t before = featureCount(wf);
	while (mergeOnce(
	    wf.lines, [&](auto& a, auto& b) { return sameLine(a, b, o); }, joinLines))
	{
	}
	while (mergeOnce(
	    wf.conics, [&](auto& a, auto& b) { return sameConic(a, b, o); }, joinConics))
	{
	}
	pruneCliques(wf);
	return before - featureCount(wf);
}

}  // namespace mrolr::model
