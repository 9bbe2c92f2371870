// The table top from one stereo scene: horizontal features at a height, sides standing on it.
#include <mrolr/recog/plane/TablePlaneEstimate.h>

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>

namespace mrolr::recog
{
namespace
{
double rad(double deg)
{
	return deg * M_PI / 180.0;
}

/** A horizontal scene feature: its height along up, its length and its points. */
struct Flat
{
	double h_mm = 0, length_mm = 0;
	std::vector<Eigen::Vector3d> points;
	Eigen::Vector3d direction = Eigen::Vector3d::Zero();  ///< zero for a conic
};

std::vector<Flat> flatFeatures(const model::WireFrame& s, const Eigen::Vector3d& up,
                               const TablePlaneOptions& o)
{
	std::vector<Flat> out;
	for (const auto& l : s.lines)
	{
		if (l.length() < o.min_line_mm || std::abs(l.direction().dot(up)) > std::sin(rad(o.horizontal_tol_deg)))
			continue;
		out.push_back({0.5 * (l.p1 + l.p2).dot(up), l.length(), {l.p1, l.p2}, l.direction()});
	}
	for (const auto& c : s.conics)
	{
		if (std::abs(c.normal.normalized().dot(up)) < std::cos(rad(o.horizontal_tol_deg))) continue;
		const double arc_mm = 0.5 * (c.a + c.b) * std::abs(c.t2 - c.t1);
		if (arc_mm < o.min_line_mm) continue;
		Flat f{c.centre.dot(up), arc_mm, {}, Eigen::Vector3d::Zero()};
		for (int k = 0; k <= 4; ++k) f.points.push_back(c.pointAt(c.t1 + k * (c.t2 - c.t1) / 4));
		out.push_back(f);
	}
	return out;
}

/** A near-vertical line: the heights of its lower and upper ends and its length. */
struct Upright
{
	double low_mm = 0, high_mm = 0, length_mm = 0;
};

std::vector<Upright> uprightFeatures(const model::WireFrame& s, const Eigen::Vector3d& up,
                                     const TablePlaneOptions& o)
{
	std::vector<Upright> out;
	for (const auto& l : s.lines)
		if (l.length() >= o.min_line_mm &&
		    std::abs(l.direction().dot(up)) >= std::cos(rad(o.vertical_tol_deg)))
			out.push_back({std::min(l.p1.dot(up), l.p2.dot(up)), std::max(l.p1.dot(up), l.p2.dot(up)),
			               l.length()});
	return out;
}

/** Length of the sides standing on @p h that rise at least stand_min_mm (not the slab's edge). */
double standingAt(double h, const std::vector<Upright>& uprights, const TablePlaneOptions& o)
{
	double len = 0;
	for (const auto& u : uprights)
		if (std::abs(u.low_mm - h) <= o.stand_tol_mm && u.length_mm >= o.stand_min_mm)
			len += u.length_mm;
	return len;
}

/** Length of the horizontal features at @p h, plus that of the sides standing on it, less that
 * of the sides ending under it (an object's top, a leg under the slab). */
double scoreAt(double h, const std::vector<Flat>& flats, const std::vector<Upright>& uprights,
               const TablePlaneOptions& o)
{
	double score = 0;
	for (const auto& f : flats)
		if (std::abs(f.h_mm - h) <= o.cluster_mm) score += f.length_mm;
	for (const auto& u : uprights)
	{
		if (std::abs(u.low_mm - h) <= o.stand_tol_mm) score += u.length_mm;
		if (std::abs(u.high_mm - h) <= o.stand_tol_mm) score -= u.length_mm;
	}
	return score;
}

bool nearAny(double h, const std::vector<double>& expected, double window)
{
	for (double e : expected)
		if (std::abs(h - e) <= window) return true;
	return false;
}

/** A weighted plane fit through the features' points; kept only when well spread and near up. */
bool fitNormal(const std::vector<const Flat*>& at, const Eigen::Vector3d& up,
               const TablePlaneOptions& o, SupportPlane& plane)
{
	// the features must span the plane: two directions at least 30 deg apart, or a conic
	bool spread = false;
	for (size_t i = 0; i < at.size() && !spread; ++i)
		for (size_t j = i + 1; j < at.size() && !spread; ++j)
			spread = at[i]->direction.isZero() || at[j]->direction.isZero() ||
			         std::abs(at[i]->direction.dot(at[j]->direction)) < std::cos(rad(30));
	if (!spread) return false;
	Eigen::Vector3d mean = Eigen::Vector3d::Zero();
	double w = 0;
	for (const auto* f : at)
		for (const auto& p : f->points) mean += f->length_mm * p, w += f->length_mm;
	mean /= w;
	Eigen::Matrix3d C = Eigen::Matrix3d::Zero();
	for (const auto* f : at)
		for (const auto& p : f->points) C += f->length_mm * (p - mean) * (p - mean).transpose();
	Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es(C);
	Eigen::Vector3d n = es.eigenvectors().col(0);
	if (n.dot(up) < 0) n = -n;
	if (std::acos(std::min(1.0, n.dot(up))) > rad(o.max_tilt_deg)) return false;
	plane = SupportPlane::through(mean, n);
	return true;
}
}  // namespace

TablePlaneEstimate estimateTablePlane(const model::WireFrame& scene_S, const Eigen::Vector3d& up_S,
                                      const std::vector<double>& expected_heights_mm,
                                      const TablePlaneOptions& o)
{
	TablePlaneEstimate r;
	const Eigen::Vector3d up = up_S.normalized();
	const auto flats = flatFeatures(scene_S, up, o);
	const auto uprights = uprightFeatures(scene_S, up, o);
	// the best-scored height, then the lowest one nearly as good that something stands on: the
	// objects stand on the table, their tops and the boxes' lids lie above it
	struct Candidate
	{
		double h_mm, score, standing_mm;
	};
	std::vector<Candidate> candidates;
	for (const auto& c : flats)
	{
		if (!nearAny(c.h_mm, expected_heights_mm, o.window_mm)) continue;
		candidates.push_back({c.h_mm, scoreAt(c.h_mm, flats, uprights, o),
		                      standingAt(c.h_mm, uprights, o)});
	}
	// heights that sides stand on, when there are any; the best of them, then the lowest nearly
	// as good
	const bool any_standing = std::any_of(candidates.begin(), candidates.end(),
	                                      [](const Candidate& c) { return c.standing_mm > 0; });
	const auto eligible = [&](const Candidate& c) { return c.standing_mm > 0 || !any_standing; };
	double best_h = 0, best_score = 0;
	for (const auto& c : candidates)
		if (eligible(c) && c.score > best_score) best_score = c.score, best_h = c.h_mm;
	r.support_mm = best_score;
	for (const auto& c : candidates)
		if (eligible(c) && c.score >= o.lower_share * best_score && c.h_mm < best_h)
			r.support_mm = c.score, best_h = c.h_mm;
	if (r.support_mm <= 0)
	{
		r.reason = "no horizontal scene feature within " + std::to_string(o.window_mm) +
		           " mm of an expected table height";
		return r;
	}
	// the mean height of the chosen cluster, weighted by length
	std::vector<const Flat*> at;
	double sum = 0, w = 0;
	for (const auto& f : flats)
		if (std::abs(f.h_mm - best_h) <= o.cluster_mm)
			at.push_back(&f), sum += f.length_mm * f.h_mm, w += f.length_mm;
	for (const auto& u : uprights)
		if (std::abs(u.low_mm - best_h) <= o.stand_tol_mm && u.length_mm >= o.stand_min_mm)
			++r.standing;
	r.horizontal = static_cast<int>(at.size());
	r.plane = SupportPlane::through(up * (sum / w), up);
	r.normal_fitted = o.fit_normal && fitNormal(at, up, o, r.plane);
	r.found = true;
	return r;
}

}  // namespace mrolr::recog
