#include <mrolr/stereo/HorizontalEdges.h>

#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>
#include <set>

namespace mrolr::stereo
{
namespace
{
/** A straight piece [lo, hi) of a left string. */
struct Piece
{
	int string = 0;
	size_t lo = 0, hi = 0;
};

double chordDistance(const EdgeString& s, size_t lo, size_t hi, size_t& worst)
{
	const cv::Point2d a = s[lo].p, ab = s[hi - 1].p - a;
	const double len = std::max(cv::norm(ab), 1e-9);
	double best = -1;
	for (size_t i = lo + 1; i + 1 < hi; ++i)
	{
		const double d = std::abs((s[i].p - a).cross(ab)) / len;
		if (d > best) best = d, worst = i;
	}
	return best;
}

void straightPieces(const EdgeString& s, int id, size_t lo, size_t hi, const FitOptions& o,
                    std::vector<Piece>& out)
{
	if (hi - lo < static_cast<size_t>(o.min_line_edgels)) return;
	size_t worst = (lo + hi) / 2;
	if (chordDistance(s, lo, hi, worst) <= o.line_tol_px) return out.push_back({id, lo, hi});
	straightPieces(s, id, lo, worst, o, out);
	straightPieces(s, id, worst, hi, o, out);
}

bool nearHorizontal(const EdgeString& s, const Piece& p, double max_deg)
{
	const cv::Point2d d = s[p.hi - 1].p - s[p.lo].p;
	return std::abs(d.y) <= std::tan(max_deg * M_PI / 180) * std::abs(d.x);
}

/** Median disparity of the matches of the same string within r px of q (the edges meeting at the
 * corner, not a nearer object passing by), or NaN. */
double disparityNear(const cv::Point2d& q, int string, const std::vector<EdgeMatch>& m, double r)
{
	std::vector<double> d;
	for (const auto& x : m)
		if (x.string == string && std::hypot(x.x_left_px - q.x, x.y_px - q.y) <= r)
			d.push_back(x.disparity_px);
	if (d.empty()) return std::nan("");
	std::nth_element(d.begin(), d.begin() + static_cast<long>(d.size() / 2), d.end());
	return d[d.size() / 2];
}

/** Distance (px) to the nearest right edgel, per pixel. */
cv::Mat rightDistance(const std::vector<EdgeString>& right, cv::Size size)
{
	cv::Mat not_edge(size, CV_8U, cv::Scalar(255));
	for (const auto& s : right)
		for (const auto& e : s)
		{
			const cv::Point q(cvRound(e.p.x), cvRound(e.p.y));
			if (q.inside(cv::Rect({0, 0}, size))) not_edge.at<uchar>(q) = 0;
		}
	cv::Mat dist;
	cv::distanceTransform(not_edge, dist, cv::DIST_L2, 3);
	return dist;
}

double rightSupport(const cv::Mat& dist, cv::Point2d a, cv::Point2d b)
{
	const int n = std::max(2, static_cast<int>(cv::norm(b - a)));
	int ok = 0;
	for (int i = 0; i <= n; ++i)
	{
		const cv::Point2d q = a + (b - a) * (static_cast<double>(i) / n);
		const cv::Point p(cvRound(q.x), cvRound(q.y));
		ok += p.inside(cv::Rect(0, 0, dist.cols, dist.rows)) && dist.at<float>(p) <= 1.5f;
	}
	return static_cast<double>(ok) / (n + 1);
}

std::set<std::pair<int, int>> matchedEdgels(const std::vector<EdgeMatch>& m)
{
	std::set<std::pair<int, int>> s;
	for (const auto& x : m) s.insert({x.string, x.edgel});
	return s;
}
}  // namespace

std::vector<LineFit3> recoverHorizontalLines(const std::vector<EdgeString>& left,
                                             const std::vector<EdgeString>& right,
                                             const std::vector<EdgeMatch>& matches,
                                             const Rectifier& rect, cv::Size right_size,
                                             const FitOptions& fit, const HorizontalOptions& o)
{
	std::vector<LineFit3> out;
	if (!o.enabled) return out;
	const cv::Mat dist = rightDistance(right, right_size);
	const auto matched = matchedEdgels(matches);
	std::vector<Piece> pieces;
	for (size_t s = 0; s < left.size(); ++s)
		straightPieces(left[s], static_cast<int>(s), 0, left[s].size(), fit, pieces);
	for (const auto& p : pieces)
	{
		const EdgeString& s = left[p.string];
		size_t n_matched = 0;
		for (size_t i = p.lo; i < p.hi; ++i)
			n_matched += matched.count({p.string, static_cast<int>(i)});
		if (!nearHorizontal(s, p, o.max_angle_deg) || n_matched > (p.hi - p.lo) / 3) continue;
		const cv::Point2d a = s[p.lo].p, b = s[p.hi - 1].p;
		const double da = disparityNear(a, p.string, matches, o.corner_radius_px),
		             db = disparityNear(b, p.string, matches, o.corner_radius_px);
		if (std::isnan(da) || std::isnan(db)) continue;
		if (rightSupport(dist, a - cv::Point2d(da, 0), b - cv::Point2d(db, 0)) <
		    o.min_right_support)
			continue;
		out.push_back({rect.pointInLeftCamera(a.x, a.y, da), rect.pointInLeftCamera(b.x, b.y, db),
		               0, static_cast<int>(p.hi - p.lo)});
	}
	return out;
}

}  // namespace mrolr::stereo
