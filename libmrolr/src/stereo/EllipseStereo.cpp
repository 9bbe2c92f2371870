#include <mrolr/stereo/EllipseStereo.h>

#include <algorithm>
#include <cmath>
#include <optional>

namespace mrolr::stereo
{
namespace
{
/** Top and bottom points (extreme rows) of an image ellipse. */
std::pair<cv::Point2d, cv::Point2d> rowExtremes(const cv::RotatedRect& el)
{
	const double th = el.angle * M_PI / 180, a = el.size.width / 2, b = el.size.height / 2;
	const double phi = std::atan2(b * std::cos(th), a * std::sin(th));  // dy/dphi = 0
	auto at = [&](double f)
	{
		return cv::Point2d(
		    el.center.x + a * std::cos(f) * std::cos(th) - b * std::sin(f) * std::sin(th),
		    el.center.y + a * std::cos(f) * std::sin(th) + b * std::sin(f) * std::cos(th));
	};
	const cv::Point2d p = at(phi), q = at(phi + M_PI);
	return p.y < q.y ? std::pair(p, q) : std::pair(q, p);
}

/** The two columns where row y crosses an image ellipse (ascending), or false. */
bool rowCrossing(const cv::RotatedRect& el, double y, double& x1, double& x2)
{
	const double th = el.angle * M_PI / 180, a = el.size.width / 2, b = el.size.height / 2;
	const double A = a * std::sin(th), B = b * std::cos(th), C = y - el.center.y;
	const double R = std::hypot(A, B);
	if (R <= 0 || std::abs(C) >= R) return false;
	const double base = std::atan2(B, A), off = std::acos(C / R);
	auto x = [&](double f)
	{ return el.center.x + a * std::cos(f) * std::cos(th) - b * std::sin(f) * std::sin(th); };
	x1 = x(base - off);
	x2 = x(base + off);
	if (x1 > x2) std::swap(x1, x2);
	return true;
}

bool nearPoints(const cv::Point2d& q, const std::vector<cv::Point2d>& pts)
{
	for (const auto& p : pts)
		if (cv::norm(p - q) <= 1.5) return true;
	return false;
}

/** A left or right image arc: its ellipse and its edgels. */
struct Arc
{
	const cv::RotatedRect* el;
	std::vector<cv::Point2d> pts;
};

/** Largest row difference of the extreme points seen on both arcs (the row difference of the
 * centres when neither extreme is seen on both). */
double extremeRowError(const Arc& l, const Arc& r)
{
	const auto [lt, lb] = rowExtremes(*l.el);
	const auto [rt, rb] = rowExtremes(*r.el);
	double err = -1;
	for (const auto& [pl, pr] : {std::pair(lt, rt), std::pair(lb, rb)})
		if (nearPoints(pl, l.pts) && nearPoints(pr, r.pts))
			err = std::max(err, std::abs(pl.y - pr.y));
	return err >= 0 ? err : std::abs(l.el->center.y - r.el->center.y);
}

/** The right arc most consistent with a left arc (extreme rows within 2 px, centre disparity in
 * range, semi-axes within 25 %), or nothing. */
std::optional<Arc> rightArc(const PieceStereoInput& in, const Arc& l)
{
	double best = 2;
	std::optional<Arc> out;
	const double la = std::max(l.el->size.width, l.el->size.height);
	for (const auto& r : in.right_pieces)
	{
		if (r.is_line) continue;
		const double d = l.el->center.x - r.ellipse.center.x;
		const double ra = std::max(r.ellipse.size.width, r.ellipse.size.height);
		if (d < in.d_min_px || d > in.d_max_px || std::abs(ra - la) > 0.25 * la) continue;
		Arc cand{&r.ellipse, piecePoints(*in.right_strings, r)};
		if (const double err = extremeRowError(l, cand); err < best) best = err, out = cand;
	}
	return out;
}

}  // namespace

std::vector<StereoEdgel> ellipsePairSamples(const PieceStereoInput& in, const ImagePiece& p,
                                            const Rectifier& rect)
{
	std::vector<StereoEdgel> out;
	const Arc l{&p.ellipse, piecePoints(in.left_strings, p)};
	const auto r = rightArc(in, l);
	if (!r) return out;
	auto add = [&](cv::Point2d a, cv::Point2d b)
	{
		if (nearPoints(a, l.pts) && nearPoints(b, r->pts))
			out.push_back({a, a.x - b.x, rect.pointInLeftCamera(a.x, a.y, a.x - b.x)});
	};
	const auto [lt, lb] = rowExtremes(*l.el);
	const auto [rt, rb] = rowExtremes(*r->el);
	add(lt, rt);
	add(lb, rb);
	const int n = 40;
	for (int k = 1; k < n; ++k)
	{
		const double y = lt.y + (lb.y - lt.y) * k / n;
		double l1, l2, r1, r2;
		if (!rowCrossing(*l.el, y, l1, l2) || !rowCrossing(*r->el, y, r1, r2)) continue;
		add({l1, y}, {r1, y});
		add({l2, y}, {r2, y});
	}
	return out;
}

}  // namespace mrolr::stereo
