// Which model explains a place better (Rivals.h).
#include <mrolr/recog/Rivals.h>

#include <algorithm>
#include <cmath>

namespace mrolr::recog
{
namespace
{
double across(const Eigen::Vector3d& d_O) { return std::hypot(d_O.x(), d_O.y()); }

/** The points of @p wf: its lines' ends and its conics' arcs in 360 steps (a full circle's
 * radius then comes out at most 0.004 % short). */
std::vector<Eigen::Vector3d> pointsOf(const model::WireFrame& wf)
{
	std::vector<Eigen::Vector3d> out;
	for (const auto& l : wf.lines) out.insert(out.end(), {l.p1, l.p2});
	for (const auto& c : wf.conics)
		for (int k = 0; k <= 360; ++k) out.push_back(c.pointAt(c.t1 + (c.t2 - c.t1) * k / 360));
	return out;
}

Eigen::Vector3d inScene(const PlacedAnswer& a)
{
	return a.result->T_OinS * a.footprint.centre_O;
}
}  // namespace

Footprint footprintOf(const model::WireFrame& wf)
{
	Footprint f;
	const auto points = pointsOf(wf);
	if (points.empty()) return f;
	Eigen::Vector3d lo = points.front(), hi = points.front();
	for (const auto& p : points) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
	f.centre_O = 0.5 * (lo + hi);
	for (const auto& p : points) f.radius_mm = std::max(f.radius_mm, across(p - f.centre_O));
	return f;
}

std::optional<size_t> betterExplained(const PlacedAnswer& target,
                                      const std::vector<PlacedAnswer>& rivals,
                                      const Eigen::Vector3d& up_S)
{
	if (!target.result || !target.result->found || !target.result->image_score) return {};
	const Eigen::Vector3d c_S = inScene(target);
	std::optional<size_t> best;
	double best_score = *target.result->image_score;
	for (size_t i = 0; i < rivals.size(); ++i)
	{
		const auto* r = rivals[i].result;
		if (!r || !r->found || !r->image_score || *r->image_score <= best_score) continue;
		const Eigen::Vector3d d_S = inScene(rivals[i]) - c_S;
		const double apart_mm = (d_S - d_S.dot(up_S) * up_S).norm();
		if (apart_mm >= std::max(target.footprint.radius_mm, rivals[i].footprint.radius_mm))
			continue;
		best = i;
		best_score = *r->image_score;
	}
	return best;
}

}  // namespace mrolr::recog
