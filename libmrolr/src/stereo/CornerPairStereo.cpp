#include <mrolr/stereo/CornerPairStereo.h>

#include <algorithm>
#include <cmath>

namespace mrolr::stereo
{
namespace
{
/** A piece's two end corners, ordered by x (px), or nothing if an end is not a corner. */
struct Corners
{
	cv::Point2d first, second;
};

/** The corner at end @p end of piece i: the intersection with another line piece (of any string:
 * edge chains often break at corners, or round them with a short arc) that ends within 8 px of
 * it, the intersection within 6 px of both ends. */
std::optional<cv::Point2d> cornerAt(const std::vector<ImagePiece>& pieces, size_t i,
                                    cv::Point2d end)
{
	std::optional<cv::Point2d> best;
	for (size_t j = 0; j < pieces.size(); ++j)
	{
		const ImagePiece& n = pieces[j];
		if (j == i || !n.is_line) continue;
		const cv::Point2d n_end = cv::norm(n.a - end) < cv::norm(n.b - end) ? n.a : n.b;
		if (cv::norm(n_end - end) > 8) continue;
		const auto x = lineIntersection(pieces[i].a, pieces[i].b, n.a, n.b);
		if (!x || cv::norm(*x - end) > 6 || cv::norm(*x - n_end) > 6) continue;
		if (!best || cv::norm(*x - end) < cv::norm(*best - end)) best = *x;
	}
	return best;
}

std::optional<Corners> corners(const std::vector<ImagePiece>& pieces, size_t i)
{
	const auto c1 = cornerAt(pieces, i, pieces[i].a), c2 = cornerAt(pieces, i, pieces[i].b);
	if (!c1 || !c2) return std::nullopt;
	return c1->x <= c2->x ? Corners{*c1, *c2} : Corners{*c2, *c1};
}

bool alongScanline(const ImagePiece& p, double deg)
{
	const cv::Point2d v = p.b - p.a;
	return p.is_line && std::abs(v.y) <= std::tan(deg * M_PI / 180) * std::abs(v.x);
}

/** Cost of pairing left corners @p l with right corners @p r (rows, grey sides), or a negative
 * value when they cannot pair. */
double pairCost(const PieceStereoInput& in, const ImagePiece& lp, const Corners& l,
                const ImagePiece& rp, const Corners& r, const SegmentStereoOptions& o)
{
	const double e1 = std::abs(l.first.y - r.first.y), e2 = std::abs(l.second.y - r.second.y);
	const double d1 = l.first.x - r.first.x, d2 = l.second.x - r.second.x;
	const double side =
	    std::min(std::abs(lp.side_left - rp.side_left), std::abs(lp.side_right - rp.side_right));
	const auto inRange = [&](double d) { return d >= in.d_min_px && d <= in.d_max_px; };
	if (e1 > o.corner_row_tol_px || e2 > o.corner_row_tol_px || !inRange(d1) || !inRange(d2) ||
	    side > o.max_side_diff_grey ||
	    std::abs(d2 - d1) > o.max_disparity_gradient * cv::norm(l.second - l.first))
		return -1;
	return (e1 + e2) / o.corner_row_tol_px + side / o.max_side_diff_grey;
}
}  // namespace

std::optional<LineFit3> cornerPairLine(const PieceStereoInput& in, size_t left_index,
                                       const Rectifier& rect, const SegmentStereoOptions& o)
{
	const ImagePiece& lp = in.left_pieces[left_index];
	if (!in.right_strings || !alongScanline(lp, o.horizontal_deg)) return std::nullopt;
	const auto l = corners(in.left_pieces, left_index);
	if (!l) return std::nullopt;
	double best = -1, second = -1;
	Corners pick{};
	for (size_t j = 0; j < in.right_pieces.size(); ++j)
	{
		if (!alongScanline(in.right_pieces[j], o.horizontal_deg)) continue;
		const auto r = corners(in.right_pieces, j);
		const double c = r ? pairCost(in, lp, *l, in.right_pieces[j], *r, o) : -1;
		if (c < 0) continue;
		if (best < 0 || c < best)
			second = best, best = c, pick = *r;
		else if (second < 0 || c < second)
			second = c;
	}
	if (best < 0 || (second >= 0 && second < best + 0.5)) return std::nullopt;  // ambiguous
	const double d1 = l->first.x - pick.first.x, d2 = l->second.x - pick.second.x;
	return LineFit3{rect.pointInLeftCamera(l->first.x, l->first.y, d1),
	                rect.pointInLeftCamera(l->second.x, l->second.y, d2), 0,
	                static_cast<int>(lp.hi - lp.lo)};
}

}  // namespace mrolr::stereo
