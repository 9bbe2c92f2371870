#include <mrolr/stereo/ImagePieces.h>

#include <opencv2/imgproc.hpp>

#include <cmath>
#include <optional>

namespace mrolr::stereo
{
namespace
{
/** Largest distance of the points [lo, hi) from their chord, and where. */
double chordDistance(const std::vector<cv::Point2d>& p, size_t lo, size_t hi, size_t& worst)
{
	const cv::Point2d a = p[lo], ab = p[hi - 1] - a;
	const double len = cv::norm(ab);
	double best = -1;
	worst = (lo + hi) / 2;
	for (size_t i = lo + 1; i + 1 < hi; ++i)
	{
		const double d = len > 2 ? std::abs((p[i] - a).cross(ab)) / len : cv::norm(p[i] - a);
		if (d > best) best = d, worst = i;
	}
	return best;
}

double meanGrey(const cv::Mat& g, cv::Point2d a, cv::Point2d b, cv::Point2d offset)
{
	const int n = std::max(2, static_cast<int>(cv::norm(b - a)));
	double sum = 0;
	int k = 0;
	for (int i = 1; i < n; ++i)
	{
		const cv::Point q(cvRound(a.x + (b.x - a.x) * i / n + offset.x),
		                  cvRound(a.y + (b.y - a.y) * i / n + offset.y));
		if (!q.inside(cv::Rect(0, 0, g.cols, g.rows))) continue;
		sum += g.at<uchar>(q);
		++k;
	}
	return k ? sum / k : -1;
}

ImagePiece linePiece(const std::vector<cv::Point2d>& p, int s, size_t lo, size_t hi,
                     const cv::Mat& g)
{
	std::vector<cv::Point2f> q(p.begin() + static_cast<long>(lo),
	                           p.begin() + static_cast<long>(hi));
	cv::Vec4f l;
	cv::fitLine(q, l, cv::DIST_L2, 0, 0.01, 0.01);
	const cv::Point2d v(l[0], l[1]), c(l[2], l[3]);
	ImagePiece out{s, lo, hi, true, {}, {}, {}};
	out.a = c + v * (p[lo] - c).dot(v);
	out.b = c + v * (p[hi - 1] - c).dot(v);
	if (out.a.y > out.b.y + 1e-9 || (std::abs(out.a.y - out.b.y) < 1e-9 && out.a.x > out.b.x))
		std::swap(out.a, out.b);
	const cv::Point2d t = (out.b - out.a) / cv::norm(out.b - out.a), n(-t.y, t.x);
	out.side_left = meanGrey(g, out.a, out.b, 2.5 * n);
	out.side_right = meanGrey(g, out.a, out.b, -2.5 * n);
	return out;
}

void split(const std::vector<cv::Point2d>& p, int s, size_t lo, size_t hi, const cv::Mat& g,
           const FitOptions& o, std::vector<ImagePiece>& out)
{
	if (hi - lo < static_cast<size_t>(std::max(3, o.min_line_edgels))) return;
	size_t worst = 0;
	if (chordDistance(p, lo, hi, worst) <= o.line_tol_px)
		return out.push_back(linePiece(p, s, lo, hi, g));
	if (hi - lo >= static_cast<size_t>(o.min_conic_edgels))
	{
		const std::vector<cv::Point2d> arc(p.begin() + static_cast<long>(lo),
		                                   p.begin() + static_cast<long>(hi));
		if (auto el = fitEllipse2D(arc, o))
		{
			ImagePiece e{s, lo, hi, false, {}, {}, {}};
			e.ellipse = *el;
			return out.push_back(e);
		}
	}
	split(p, s, lo, worst, g, o, out);
	split(p, s, worst, hi, g, o, out);
}
/** Do two consecutive line pieces turn by less than 45°, as the chords of a flat image ellipse do
 * (a box corner turns more)? */
bool smoothTurn(const ImagePiece& a, const ImagePiece& b)
{
	const cv::Point2d u = a.b - a.a, v = b.b - b.a;
	return std::abs(u.dot(v)) >= std::cos(M_PI / 4) * cv::norm(u) * cv::norm(v);
}

/** Can pieces a and b (consecutive in one string) belong to one image ellipse: adjacent (at most
 * a dropped short piece between them) and, for two lines, turning smoothly? */
bool mayJoin(const ImagePiece& a, const ImagePiece& b, const FitOptions& o)
{
	return b.lo <= a.hi + static_cast<size_t>(o.min_line_edgels) &&
	       (!a.is_line || !b.is_line || smoothTurn(a, b));
}

/** Joins runs of neighbouring pieces of one string into one arc when their union is elliptical
 * (the longest such run from each piece): the top-down split cuts a rim at its lowest point, a
 * quarter of an ellipse is too short for a reliable fit, and a flat rim seen nearly edge-on is
 * split into short chords that are each straight within line_tol_px. */
void mergeArcs(const std::vector<cv::Point2d>& p, const FitOptions& o,
               std::vector<ImagePiece>& pieces)
{
	for (size_t i = 0; i + 1 < pieces.size(); ++i)
	{
		size_t last = i;
		std::optional<cv::RotatedRect> best;
		for (size_t j = i + 1; j < pieces.size() && mayJoin(pieces[j - 1], pieces[j], o); ++j)
			if (auto el = fitEllipse2D({p.begin() + static_cast<long>(pieces[i].lo),
			                            p.begin() + static_cast<long>(pieces[j].hi)},
			                           o))
				last = j, best = el;
		if (!best) continue;
		pieces[i].is_line = false;
		pieces[i].ellipse = *best;
		pieces[i].hi = pieces[last].hi;
		pieces.erase(pieces.begin() + static_cast<long>(i) + 1,
		             pieces.begin() + static_cast<long>(last) + 1);
	}
}
}  // namespace

std::optional<cv::Point2d> lineIntersection(cv::Point2d a, cv::Point2d b, cv::Point2d c,
                                            cv::Point2d d)
{
	const cv::Point2d u = b - a, v = d - c;
	const double den = u.cross(v);
	if (std::abs(den) < std::sin(20 * M_PI / 180) * cv::norm(u) * cv::norm(v)) return std::nullopt;
	return a + u * ((c - a).cross(v) / den);
}

std::vector<cv::Point2d> piecePoints(const std::vector<EdgeString>& strings, const ImagePiece& p)
{
	std::vector<cv::Point2d> out;
	for (size_t i = p.lo; i < p.hi; ++i) out.push_back(strings[p.string][i].p);
	return out;
}

std::vector<ImagePiece> segmentImageStrings(const std::vector<EdgeString>& strings,
                                            const cv::Mat& grey, const FitOptions& o)
{
	std::vector<ImagePiece> out;
	for (size_t s = 0; s < strings.size(); ++s)
	{
		std::vector<cv::Point2d> p;
		for (const auto& e : strings[s]) p.push_back(e.p);
		std::vector<ImagePiece> pieces;
		split(p, static_cast<int>(s), 0, p.size(), grey, o, pieces);
		mergeArcs(p, o, pieces);
		out.insert(out.end(), pieces.begin(), pieces.end());
	}
	return out;
}

}  // namespace mrolr::stereo
