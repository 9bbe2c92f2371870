// Edge-pair hypotheses on the support plane (PlaneHypotheses.h): two scene lines along the plane's
// normal taken as two vertical edges of the model (a box's), as far apart as they.
#include <mrolr/recog/plane/PlaneHypotheses.h>

#include "../UprightPose.h"

#include <algorithm>
#include <cmath>

namespace mrolr::recog
{
namespace
{
/** A scene line's horizontal position in the plane's basis (h1, h2) and its height range. */
struct Vertical
{
	Eigen::Vector2d xy;
	double h_lo, h_hi;
};
}  // namespace

void PlaneHypothesisGenerator::findVerticalEdgePairs()
{
	const double vertical_cos = std::cos(opts_.limb_vertical_tol_deg * M_PI / 180);
	std::vector<size_t> v;
	for (size_t k = 0; k < model_.size(); ++k)
		if (model_[k].isLine() && model_[k].len_mm >= opts_.edge_pair_min_mm &&
		    std::abs(model_[k].u.z()) >= vertical_cos)
			v.push_back(k);
	for (size_t a = 0; a < v.size(); ++a)
		for (size_t b = a + 1; b < v.size(); ++b)
		{
			const Feature &fi = model_[v[a]], &fj = model_[v[b]];
			VerticalEdgePair p;
			p.i = v[a], p.j = v[b];
			p.xy_i = fi.m.head<2>(), p.xy_j = fj.m.head<2>();
			p.width_mm = (p.xy_j - p.xy_i).norm();
			// two edges closer than a tolerance apart are one edge built twice
			if (p.width_mm <= 2 * opts_.edge_pair_width_tol_mm) continue;
			p.z_lo_mm = std::min({fi.p1.z(), fi.p2.z(), fj.p1.z(), fj.p2.z()});
			p.z_hi_mm = std::max({fi.p1.z(), fi.p2.z(), fj.p1.z(), fj.p2.z()});
			edge_pairs_.push_back(p);
		}
}

void PlaneHypothesisGenerator::addEdgePairHypotheses(const std::vector<Feature>& scene,
                                                     const std::vector<size_t>& verticals,
                                                     const SupportPlane& plane,
                                                     std::vector<PlaneHypothesis>& out) const
{
	const Eigen::Vector3d& n = plane.n_S;
	const auto [h1, h2] = detail::horizontalBasis(n);
	std::vector<Vertical> vs;
	for (const size_t s : verticals)
	{
		const Feature& f = scene[s];
		const double a = plane.height_mm(f.p1), b = plane.height_mm(f.p2);
		vs.push_back({{f.m.dot(h1), f.m.dot(h2)}, std::min(a, b), std::max(a, b)});
	}
	const double tol = opts_.height_tol_mm;
	for (size_t a = 0; a < vs.size(); ++a)
		for (size_t b = 0; b < vs.size(); ++b)  // both orders: both assignments
		{
			if (a == b) continue;
			const Eigen::Vector2d d_S = vs[b].xy - vs[a].xy;
			const double width = d_S.norm();
			for (const VerticalEdgePair& p : edge_pairs_)
			{
				if (std::abs(width - p.width_mm) > opts_.edge_pair_width_tol_mm ||
				    std::min(vs[a].h_lo, vs[b].h_lo) < p.z_lo_mm - base_z_mm_ - tol ||
				    std::max(vs[a].h_hi, vs[b].h_hi) > p.z_hi_mm - base_z_mm_ + tol)
					continue;
				const Eigen::Vector2d d_O = p.xy_j - p.xy_i;
				const double yaw = std::atan2(d_S.y(), d_S.x()) - std::atan2(d_O.y(), d_O.x());
				PlaneHypothesis h;
				h.T_OinS.linear() = detail::uprightRotation(n, yaw);
				const Eigen::Vector2d mid_S = 0.5 * (vs[a].xy + vs[b].xy);
				const Eigen::Vector2d mid_O = 0.5 * (p.xy_i + p.xy_j);
				const Eigen::Vector3d mid_O3(mid_O.x(), mid_O.y(), 0);
				h.T_OinS.translation() = detail::standOn(
				    mid_S.x() * h1 + mid_S.y() * h2 - h.T_OinS.linear() * mid_O3, plane, base_z_mm_);
				h.from_edge_pair = true;
				h.model_feature = static_cast<int>(p.i);
				h.scene_feature = static_cast<int>(verticals[a]);
				out.push_back(h);
			}
		}
}

}  // namespace mrolr::recog
