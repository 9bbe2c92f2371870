// Obstacle in the corridor and the side to pass it on (thesis 5.8.1.2, fig 5.8.1.4).
#include <mrolr/mission/ObstacleDetour.h>

#include <algorithm>
#include <cmath>
#include <map>

namespace mrolr::mission
{
namespace
{
constexpr double kBin_m = 0.05;  ///< width of a lateral occupancy bin

int binOf(double x)
{
	return static_cast<int>(std::floor(x / kBin_m));
}

/** The k-th smallest value (k from 0, clamped). */
double kthSmallest(std::vector<double> v, int k)
{
	const auto i = static_cast<size_t>(std::clamp(k, 0, static_cast<int>(v.size()) - 1));
	std::nth_element(v.begin(), v.begin() + static_cast<long>(i), v.end());
	return v[i];
}

/** Points per lateral (x) bin among those with z in [z0, z1]. */
std::map<int, int> lateralBins(const std::vector<Eigen::Vector3d>& p, double z0, double z1)
{
	std::map<int, int> bins;
	for (const auto& q : p)
		if (q.z() >= z0 && q.z() <= z1) ++bins[binOf(q.x())];
	return bins;
}

/** From occupied bin @p k, the last bin reached going @p dir (±1) over occupied bins (a single
 * empty bin is stepped over). */
int grow(const std::map<int, int>& bins, int k, int dir, int min_points)
{
	auto occupied = [&](int b)
	{
		const auto it = bins.find(b);
		return it != bins.end() && it->second >= min_points;
	};
	while (occupied(k + dir) || occupied(k + 2 * dir)) k += occupied(k + dir) ? dir : 2 * dir;
	return k;
}

/** Lateral extent [right, left] of the obstacle from the bins of the corridor outwards. */
void measureWidth(ObstacleSighting& s, const std::map<int, int>& bins, const ObstacleOptions& o)
{
	int lo = binOf(o.corridor_half_width_m) + 1, hi = binOf(-o.corridor_half_width_m) - 1;
	for (int b = binOf(-o.corridor_half_width_m); b <= binOf(o.corridor_half_width_m); ++b)
		if (const auto it = bins.find(b); it != bins.end() && it->second >= o.min_bin_points)
			lo = std::min(lo, b), hi = std::max(hi, b);
	if (lo > hi) return;  // thinly spread: keep the corridor points' own extent
	s.right_m = std::min(s.right_m, grow(bins, lo, -1, o.min_bin_points) * kBin_m);
	s.left_m = std::max(s.left_m, (grow(bins, hi, +1, o.min_bin_points) + 1) * kBin_m);
}

/** Far edge: from near_m outwards over occupied 5 cm depth bins of the points within the
 * lateral extent (a single empty bin is stepped over), or near_m + assumed_depth_m if further. */
double farEdge(const ObstacleSighting& s, const std::vector<Eigen::Vector3d>& p,
               const ObstacleOptions& o)
{
	std::map<int, int> bins;
	for (const auto& q : p)
		if (q.x() >= s.right_m && q.x() <= s.left_m && q.z() >= s.near_m &&
		    q.z() <= s.near_m + o.range_m)
			++bins[binOf(q.z())];
	const double seen = (grow(bins, binOf(s.near_m), +1, o.min_bin_points) + 1) * kBin_m;
	return std::max(seen, s.near_m + o.assumed_depth_m);
}
}  // namespace

ObstacleSighting obstacleAhead(const std::vector<Eigen::Vector3d>& p_inB, double corridor_length_m,
                               const ObstacleOptions& o, bool goal_at_end)
{
	const double w = o.corridor_half_width_m;
	auto inCorridor = [&](const Eigen::Vector3d& q)
	{
		if (q.z() > 0 && q.z() <= corridor_length_m && std::abs(q.x()) <= w) return true;
		return goal_at_end && std::hypot(q.z() - corridor_length_m, q.x()) <= w;
	};
	ObstacleSighting s;
	std::vector<double> z, x;
	for (const auto& q : p_inB)
		if (inCorridor(q)) z.push_back(q.z()), x.push_back(q.x());
	s.points = static_cast<int>(z.size());
	s.blocked = s.points >= o.min_points;
	if (!s.blocked) return s;
	s.near_m = kthSmallest(z, o.min_bin_points);
	s.right_m = kthSmallest(x, o.min_bin_points);
	std::vector<double> minus_x(x.size());
	std::transform(x.begin(), x.end(), minus_x.begin(), [](double v) { return -v; });
	s.left_m = -kthSmallest(minus_x, o.min_bin_points);
	measureWidth(s, lateralBins(p_inB, s.near_m - kBin_m, s.near_m + o.range_m), o);
	s.far_m = farEdge(s, p_inB, o);
	return s;
}

namespace
{
/** Obstacle points in the passage of side @p side: the corridor along x = x_side. */
int pointsInPassage(const std::vector<Eigen::Vector3d>& p, double x_side, double z_end,
                    const ObstacleOptions& o)
{
	const double w = o.corridor_half_width_m;
	return static_cast<int>(std::count_if(p.begin(), p.end(),
	                                      [&](const Eigen::Vector3d& q) {
		                                      return std::abs(q.x() - x_side) <= w && q.z() > 0 &&
		                                             q.z() <= z_end;
	                                      }));
}
}  // namespace

Detour planDetour(const ObstacleSighting& s, const std::vector<Eigen::Vector3d>& p_inB,
                  const ObstacleOptions& o)
{
	const double pass = o.corridor_half_width_m + o.clearance_m;
	const double x_left = s.left_m + pass, x_right = s.right_m - pass;
	const double z_end = s.far_m + pass;
	Detour d;
	d.points_left = pointsInPassage(p_inB, x_left, z_end, o);
	d.points_right = pointsInPassage(p_inB, x_right, z_end, o);
	const bool left_free = d.points_left < o.min_points, right_free = d.points_right < o.min_points;
	d.both_blocked = !left_free && !right_free;
	if (left_free && right_free)
		d.side = x_left <= -x_right ? +1 : -1;
	else if (left_free != right_free)
		d.side = left_free ? +1 : -1;
	else
		d.side = d.points_left <= d.points_right ? +1 : -1;
	const double x = d.side > 0 ? x_left : x_right;
	d.via_zx = {{std::max(s.near_m - pass, 0.0), x}, {z_end, x}};
	return d;
}

}  // namespace mrolr::mission
