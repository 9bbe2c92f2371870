#include <mrolr/stereo/CornerPairStereo.h>
#include <mrolr/stereo/EdgelSupport.h>
#include <mrolr/stereo/EllipseStereo.h>
#include <mrolr/stereo/SegmentStereo.h>
#include <mrolr/util/OptionsBinder.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <ostream>

namespace mrolr::stereo
{
namespace
{
using MatchIndex = std::map<std::pair<int, int>, const EdgeMatch*>;

/** A candidate segment pair and its 3D line. */
struct Pair
{
	size_t left = 0, right = 0;
	double cost = 0;
	LineFit3 line;
	cv::Point3d e1, e2;  ///< left image ends (x, y px) and their disparities (px)
};

double angleOf(const ImagePiece& p)
{
	return std::atan2(p.b.y - p.a.y, p.b.x - p.a.x);
}

double angleDiffDeg(const ImagePiece& l, const ImagePiece& r)
{
	double d = std::abs(angleOf(l) - angleOf(r));
	if (d > M_PI) d = 2 * M_PI - d;
	return std::min(d, M_PI - d) * 180 / M_PI;
}

bool nearScanline(const ImagePiece& p, double deg)
{
	const cv::Point2d v = p.b - p.a;
	return std::abs(v.y) <= std::tan(deg * M_PI / 180) * std::abs(v.x);
}

double xAtRow(const ImagePiece& p, double y)
{
	return p.a.x + (p.b.x - p.a.x) * (y - p.a.y) / (p.b.y - p.a.y);
}

/** Ends (left image point, disparity) of a matched pair of segments across the scanlines: the
 * rows both segments cover (the overlap of their epipolar extents). */
bool pairEnds(const ImagePiece& l, const ImagePiece& r, const SegmentStereoOptions& o,
              cv::Point3d& e1, cv::Point3d& e2)
{
	if (nearScanline(l, o.horizontal_deg) || nearScanline(r, o.horizontal_deg)) return false;
	const double y0 = std::max(l.a.y, r.a.y), y1 = std::min(l.b.y, r.b.y);
	const double shorter = std::min(l.b.y - l.a.y, r.b.y - r.a.y);
	if (y1 - y0 < o.min_row_overlap * shorter) return false;
	e1 = {xAtRow(l, y0), y0, xAtRow(l, y0) - xAtRow(r, y0)};
	e2 = {xAtRow(l, y1), y1, xAtRow(l, y1) - xAtRow(r, y1)};
	return true;
}

/** Median disparity of the point matches inside a left piece (NaN if none). */
double pointDisparity(const ImagePiece& p, const MatchIndex& m)
{
	std::vector<double> d;
	for (size_t i = p.lo; i < p.hi; ++i)
	{
		const auto it = m.find({p.string, static_cast<int>(i)});
		if (it != m.end()) d.push_back(it->second->disparity_px);
	}
	if (d.empty()) return std::nan("");
	std::nth_element(d.begin(), d.begin() + static_cast<long>(d.size() / 2), d.end());
	return d[d.size() / 2];
}

std::optional<Pair> tryPair(const PieceStereoInput& in, size_t i, size_t j, double d_points,
                            const Rectifier& rect, const SegmentStereoOptions& o)
{
	const ImagePiece &l = in.left_pieces[i], &r = in.right_pieces[j];
	const double ang = angleDiffDeg(l, r);
	const double sl = std::abs(l.side_left - r.side_left),
	             sr = std::abs(l.side_right - r.side_right);
	// a short piece must agree on both sides (a mark on a surface, not an occluding contour)
	const bool is_short = static_cast<int>(l.hi - l.lo) < o.both_sides_below_edgels;
	const double side = is_short ? std::max(sl, sr) : std::min(sl, sr);
	cv::Point3d e1, e2;
	if (ang > o.max_angle_diff_deg || side > o.max_side_diff_grey || !pairEnds(l, r, o, e1, e2))
		return std::nullopt;
	const auto inRange = [&](double d) { return d >= in.d_min_px && d <= in.d_max_px; };
	const double len = std::hypot(e2.x - e1.x, e2.y - e1.y);
	if (!inRange(e1.z) || !inRange(e2.z) || len < 2 ||
	    std::abs(e2.z - e1.z) > o.max_disparity_gradient * len)
		return std::nullopt;
	Pair p{i, j, ang / o.max_angle_diff_deg + side / o.max_side_diff_grey, {}, e1, e2};
	if (!std::isnan(d_points)) p.cost += std::abs(0.5 * (e1.z + e2.z) - d_points) / 2;
	p.line = {rect.pointInLeftCamera(e1.x, e1.y, e1.z), rect.pointInLeftCamera(e2.x, e2.y, e2.z), 0,
	          static_cast<int>(l.hi - l.lo)};
	return p;
}

std::vector<double> cornerDisparities(const cv::Point2d& q,
                                      const std::vector<std::optional<Pair>>& pairs,
                                      const std::vector<EdgeMatch>& matches,
                                      const SegmentStereoOptions& o);

/** Disparity of pair @p p's 3D line at row y (its linear profile, extended past its ends). */
double pairDisparityAtRow(const Pair& p, double y)
{
	if (std::abs(p.e2.y - p.e1.y) < 1e-9) return p.e1.z;
	return p.e1.z + (y - p.e1.y) / (p.e2.y - p.e1.y) * (p.e2.z - p.e1.z);
}

/** Corner consistency of candidate @p c of left piece @p l: how far (in units of
 * corner_consistency_px) its disparity at the piece's two ends is from the disparity of the other
 * matched segments (or point matches) ending there; 0 where a corner has neither. */
double cornerInconsistency(const ImagePiece& l, const Pair& c,
                           const std::vector<std::optional<Pair>>& others,
                           const std::vector<EdgeMatch>& matches, const SegmentStereoOptions& o)
{
	double cost = 0;
	for (const cv::Point2d& q : {l.a, l.b})
		if (const auto d = cornerDisparities(q, others, matches, o); !d.empty())
			cost += std::abs(pairDisparityAtRow(c, q.y) - d.front()) / o.corner_consistency_px;
	return cost;
}

/** For each left line piece its best segment pair (a right segment may serve several collinear
 * left pieces: the two images split an edge differently). With corner_consistency_px > 0 a piece
 * with several candidates chooses again, its candidates' costs raised by their corner
 * inconsistency with the other pieces' first choices. */
std::vector<std::optional<Pair>> matchSegments(const PieceStereoInput& in, const MatchIndex& m,
                                               const Rectifier& rect, const SegmentStereoOptions& o)
{
	std::vector<std::optional<Pair>> best(in.left_pieces.size());
	std::vector<std::vector<Pair>> all(in.left_pieces.size());
	for (size_t i = 0; i < in.left_pieces.size(); ++i)
	{
		if (!in.left_pieces[i].is_line) continue;
		const double dp = pointDisparity(in.left_pieces[i], m);
		for (size_t j = 0; j < in.right_pieces.size(); ++j)
			if (in.right_pieces[j].is_line)
				if (auto p = tryPair(in, i, j, dp, rect, o))
				{
					if (!best[i] || p->cost < best[i]->cost) best[i] = p;
					all[i].push_back(*p);
				}
	}
	if (o.corner_consistency_px <= 0) return best;
	auto chosen = best;
	for (size_t i = 0; i < all.size(); ++i)
	{
		if (all[i].size() < 2) continue;
		auto others = best;
		others[i].reset();  // its own line passes through its ends
		std::optional<double> c_best;
		for (const auto& c : all[i])
		{
			const double cost =
			    c.cost + cornerInconsistency(in.left_pieces[i], c, others, in.matches, o);
			if (!c_best || cost < *c_best) c_best = cost, chosen[i] = c;
		}
	}
	return chosen;
}

/** Candidate disparities at a corner q, nearest first: each matched segment passing within
 * corner_radius_px of q (its linear disparity profile, extended by corner_radius_px beyond its
 * ends), then the median of the point matches within corner_radius_px; empty if neither. */
std::vector<double> cornerDisparities(const cv::Point2d& q,
                                      const std::vector<std::optional<Pair>>& pairs,
                                      const std::vector<EdgeMatch>& matches,
                                      const SegmentStereoOptions& o)
{
	std::vector<std::pair<double, double>> by_distance;  // (px from q, disparity px)
	for (auto it = pairs.rbegin(); it != pairs.rend(); ++it)  // of two as near, the later first
	{
		const auto& p = *it;
		if (!p) continue;
		const cv::Point2d a(p->e1.x, p->e1.y), ab = cv::Point2d(p->e2.x, p->e2.y) - a;
		const double len = cv::norm(ab);
		if (len < 1) continue;
		const double t = std::clamp((q - a).dot(ab) / (len * len), -o.corner_radius_px / len,
		                            1 + o.corner_radius_px / len);
		if (const double r = cv::norm(a + t * ab - q); r <= o.corner_radius_px)
			by_distance.emplace_back(r, p->e1.z + t * (p->e2.z - p->e1.z));
	}
	std::stable_sort(by_distance.begin(), by_distance.end(),
	                 [](const auto& x, const auto& y) { return x.first < y.first; });
	std::vector<double> out;
	for (const auto& c : by_distance) out.push_back(c.second);
	std::vector<double> near;
	for (const auto& m : matches)
		if (std::hypot(m.x_left_px - q.x, m.y_px - q.y) <= o.corner_radius_px)
			near.push_back(m.disparity_px);
	if (near.empty()) return out;
	std::nth_element(near.begin(), near.begin() + static_cast<long>(near.size() / 2), near.end());
	out.push_back(near[near.size() / 2]);
	return out;
}

/** Is there a right segment near the scanline direction along the predicted right segment a → b? */
bool rightSegmentAlong(const PieceStereoInput& in, cv::Point2d a, cv::Point2d b,
                       const SegmentStereoOptions& o)
{
	const cv::Point2d mid = 0.5 * (a + b);
	for (const auto& r : in.right_pieces)
	{
		if (!r.is_line || !nearScanline(r, o.horizontal_deg)) continue;
		const cv::Point2d v = (r.b - r.a) / cv::norm(r.b - r.a);
		const double t = (mid - r.a).dot(v);
		if (t >= 0 && t <= cv::norm(r.b - r.a) && std::abs((mid - r.a).cross(v)) <= 1.5 &&
		    std::abs((b - a).cross(v)) <= o.max_angle_diff_deg * M_PI / 180 * cv::norm(b - a))
			return true;
	}
	return false;
}

/** A left piece along the scanlines placed from the disparities at its two corners (the nearest
 * candidates) when the right image shows a segment along the predicted position. */
std::optional<LineFit3> horizontalLine(const PieceStereoInput& in, const ImagePiece& l,
                                       const std::vector<std::optional<Pair>>& pairs,
                                       const Rectifier& rect, const SegmentStereoOptions& o)
{
	const auto da = cornerDisparities(l.a, pairs, in.matches, o),
	           db = cornerDisparities(l.b, pairs, in.matches, o);
	if (da.empty() || db.empty() ||
	    !rightSegmentAlong(in, l.a - cv::Point2d(da[0], 0), l.b - cv::Point2d(db[0], 0), o))
		return std::nullopt;
	return LineFit3{rect.pointInLeftCamera(l.a.x, l.a.y, da[0]),
	                rect.pointInLeftCamera(l.b.x, l.b.y, db[0]), 0, static_cast<int>(l.hi - l.lo)};
}

/** A left line piece across the scanlines that no right segment pairs with (too short in the right
 * image, or split there differently) placed from the candidate disparities at its two corners:
 * the first pair (nearest first) within the disparity range and gradient limit whose predicted
 * right segment lies on right edgels for corner_line_min_support of its length. */
std::optional<LineFit3> cornerPlacedLine(const PieceStereoInput& in, const ImagePiece& l,
                                         const std::vector<std::optional<Pair>>& pairs,
                                         const Rectifier& rect, const SegmentStereoOptions& o)
{
	if (!in.right_strings) return std::nullopt;
	const double len = cv::norm(l.b - l.a);
	const auto inRange = [&](double d) { return d >= in.d_min_px && d <= in.d_max_px; };
	for (const double da : cornerDisparities(l.a, pairs, in.matches, o))
		for (const double db : cornerDisparities(l.b, pairs, in.matches, o))
		{
			if (!inRange(da) || !inRange(db) || std::abs(db - da) > o.max_disparity_gradient * len)
				continue;
			if (edgelSupport(*in.right_strings, l.a - cv::Point2d(da, 0),
			                 l.b - cv::Point2d(db, 0), o.max_angle_diff_deg) >=
			    o.corner_line_min_support)
				return LineFit3{rect.pointInLeftCamera(l.a.x, l.a.y, da),
				                rect.pointInLeftCamera(l.b.x, l.b.y, db), 0,
				                static_cast<int>(l.hi - l.lo)};
		}
	return std::nullopt;
}

std::vector<StereoEdgel> matchedEdgels(const ImagePiece& p, const MatchIndex& m,
                                       const Rectifier& rect)
{
	std::vector<StereoEdgel> out;
	for (size_t i = p.lo; i < p.hi; ++i)
	{
		const auto it = m.find({p.string, static_cast<int>(i)});
		if (it == m.end()) continue;
		const cv::Point2d xy(it->second->x_left_px, it->second->y_px);
		out.push_back({xy, it->second->disparity_px,
		               rect.pointInLeftCamera(xy.x, xy.y, it->second->disparity_px)});
	}
	return out;
}
}  // namespace

void reconstructPieces(const PieceStereoInput& in, const Rectifier& rect, const FitOptions& fit,
                       const SegmentStereoOptions& o, std::vector<LineFit3>& lines,
                       std::vector<ConicFit3>& conics)
{
	MatchIndex m;
	for (const auto& x : in.matches) m[{x.string, x.edgel}] = &x;
	const auto pairs = matchSegments(in, m, rect, o);
	for (size_t i = 0; i < in.left_pieces.size(); ++i)
	{
		const ImagePiece& p = in.left_pieces[i];
		if (pairs[i])
		{
			lines.push_back(pairs[i]->line);
			continue;
		}
		if (p.is_line && nearScanline(p, o.horizontal_deg))
		{
			auto h = horizontalLine(in, p, pairs, rect, o);
			if (!h && o.corner_pairs) h = cornerPairLine(in, i, rect, o);
			if (h)
			{
				lines.push_back(*h);
				continue;
			}
		}
		if (p.is_line)
		{
			if (o.corner_lines)
				if (auto c = cornerPlacedLine(in, p, pairs, rect, o)) lines.push_back(*c);
			continue;  // else left to the 3D strings of the point matches
		}
		auto e = ellipsePairSamples(in, p, rect);
		if (static_cast<int>(e.size()) < 2 * o.min_conic_matches) e = matchedEdgels(p, m, rect);
		const auto arc = piecePoints(in.left_strings, p);
		if (static_cast<int>(e.size()) >= o.min_conic_matches)
		{
			if (auto c = conicFromEllipse(p.ellipse, arc, e, rect, fit)) conics.push_back(*c);
		}
	}
}

namespace
{
using O = SegmentStereoOptions;
constexpr auto kOpt = util::Presence::Optional;  // [scene]: docs/config.md

const util::OptionsBinder<O>& segmentStereoOptionsBinder()
{
	static const auto b = util::OptionsBinder<O>()
	    .flag("segment_stereo", &O::enabled, kOpt)
	    .number("segment_max_angle_diff_deg", &O::max_angle_diff_deg, 0, 90, kOpt)
	    .number("segment_min_row_overlap", &O::min_row_overlap, 0, 1, kOpt)
	    .number("segment_max_side_diff_grey", &O::max_side_diff_grey, 0, 255, kOpt)
	    .number("segment_horizontal_deg", &O::horizontal_deg, 0, 90, kOpt)
	    .number("segment_corner_radius_px", &O::corner_radius_px, 0, 100, kOpt)
	    .number("segment_duplicate_mm", &O::duplicate_mm, 0, 1000, kOpt)
	    .number("segment_max_disparity_gradient", &O::max_disparity_gradient, 0, 10, kOpt)
	    .integer("segment_min_conic_matches", &O::min_conic_matches, 3, 1000000, kOpt)
	    .flag("segment_corner_pairs", &O::corner_pairs, kOpt)
	    .number("segment_corner_row_tol_px", &O::corner_row_tol_px, 0.01, 10, kOpt)
	    .integer("segment_min_line_edgels", &O::min_line_edgels, 2, 1000000, kOpt)
	    .integer("segment_both_sides_below_edgels", &O::both_sides_below_edgels, 0, 1000000,
	             kOpt)
	    .number("segment_corner_consistency_px", &O::corner_consistency_px, 0, 100, kOpt)
	    .flag("segment_corner_lines", &O::corner_lines, kOpt)
	    .number("segment_corner_line_min_support", &O::corner_line_min_support, 0.01, 1, kOpt);
	return b;
}
}  // namespace

void SegmentStereoOptions::loadFromConfigFile(const mrpt::config::CConfigFileBase& cfg,
                                             const std::string& section)
{
	segmentStereoOptionsBinder().load(cfg, section, *this);
}

void SegmentStereoOptions::dump(std::ostream& out) const
{
	segmentStereoOptionsBinder().dump(out, *this);
}

}  // namespace mrolr::stereo
