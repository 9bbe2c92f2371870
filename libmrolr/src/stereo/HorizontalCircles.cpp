#include <mrolr/stereo/HorizontalCircles.h>

#include <Eigen/Dense>
#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

namespace mrolr::stereo
{
namespace
{
/** An orthonormal basis (e1, e2) of the plane with unit normal n. */
std::pair<Eigen::Vector3d, Eigen::Vector3d> planeBasis(const Eigen::Vector3d& n)
{
	const Eigen::Vector3d a =
	    std::abs(n.x()) < 0.9 ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitY();
	const Eigen::Vector3d e1 = (a - a.dot(n) * n).normalized();
	return {e1, n.cross(e1)};
}

/** The point of plane n·X = h on the viewing ray of pixel q, or nothing behind or along it. */
std::optional<Eigen::Vector3d> onPlane(const Rectifier& rect, const Eigen::Vector3d& n, double h,
                                       const cv::Point2d& q)
{
	const Eigen::Vector3d r = rect.leftRay(q.x, q.y);
	const double s = n.dot(r);
	if (std::abs(s) < 1e-6 || h / s <= 0) return std::nullopt;
	return Eigen::Vector3d(h / s * r);
}

double median(std::vector<double> v)
{
	std::nth_element(v.begin(), v.begin() + static_cast<long>(v.size() / 2), v.end());
	return v[v.size() / 2];
}

/** A circle in the plane coordinates (u, v): centre and radius (mm). */
struct Circle2
{
	Eigen::Vector2d c = Eigen::Vector2d::Zero();
	double r = 0;
};

/** Algebraic (Kåsa) circle through the points. */
Circle2 kasa(const std::vector<Eigen::Vector2d>& p)
{
	Eigen::MatrixXd A(p.size(), 3);
	Eigen::VectorXd b(p.size());
	for (size_t i = 0; i < p.size(); ++i)
	{
		A.row(static_cast<int>(i)) << p[i].x(), p[i].y(), 1;
		b[static_cast<int>(i)] = -p[i].squaredNorm();
	}
	const Eigen::Vector3d x = A.colPivHouseholderQr().solve(b);
	Circle2 out;
	out.c = -0.5 * x.head<2>();
	out.r = std::sqrt(std::max(0.0, out.c.squaredNorm() - x[2]));
	return out;
}

/** Gauss-Newton on the radial residuals, each weighted by its image effect (px per mm), so that
 * the edgels' accurate image positions, not their grazing depths along the plane, fix the circle.
 */
Circle2 weightedCircle(const std::vector<Eigen::Vector3d>& P, const std::vector<Eigen::Vector2d>& p,
                       const Eigen::Vector3d& e1, const Eigen::Vector3d& e2, const Rectifier& rect)
{
	Circle2 c = kasa(p);
	for (int it = 0; it < 15; ++it)
	{
		Eigen::Matrix3d H = Eigen::Matrix3d::Zero();
		Eigen::Vector3d g = Eigen::Vector3d::Zero();
		for (size_t i = 0; i < p.size(); ++i)
		{
			const Eigen::Vector2d d = p[i] - c.c;
			const double len = d.norm();
			if (len < 1e-9) continue;
			const Eigen::Vector2d u = d / len;
			const Eigen::Vector3d step = u.x() * e1 + u.y() * e2;
			const double w = cv::norm(rect.leftPixelOf(P[i] + step) - rect.leftPixelOf(P[i]));
			const Eigen::Vector3d J(-w * u.x(), -w * u.y(), -w);
			const double res = w * (len - c.r);
			H += J * J.transpose();
			g += J * res;
		}
		const Eigen::Vector3d dx = H.ldlt().solve(-g);
		if (!dx.allFinite()) break;
		c.c += dx.head<2>();
		c.r += dx[2];
		if (dx.norm() < 1e-4) break;
	}
	return c;
}

/** RMS distance (px) of the image points from the projection of the 3D circle. */
double imageRms(const std::vector<cv::Point2d>& q, const Eigen::Vector3d& centre,
                const Eigen::Vector3d& e1, const Eigen::Vector3d& e2, double r,
                const Rectifier& rect)
{
	std::vector<cv::Point2d> s;
	const int n = 1440;
	for (int k = 0; k < n; ++k)
	{
		const double t = 2 * M_PI * k / n;
		s.push_back(rect.leftPixelOf(centre + r * (std::cos(t) * e1 + std::sin(t) * e2)));
	}
	double sum = 0;
	for (const auto& x : q)
	{
		double best = 1e300;
		for (const auto& y : s)
			best = std::min(best, (x.x - y.x) * (x.x - y.x) + (x.y - y.y) * (x.y - y.y));
		sum += best;
	}
	return std::sqrt(sum / static_cast<double>(q.size()));
}

/** Arc (t1, t2) of the points' parameters about the circle (major axis e1, second axis e2). */
std::pair<double, double> arcOf(const std::vector<Eigen::Vector2d>& p, const Circle2& c)
{
	std::vector<double> t;
	for (const auto& x : p)
	{
		double a = std::atan2(x.y() - c.c.y(), x.x() - c.c.x());
		if (!t.empty())
		{
			while (a - t.back() > M_PI) a -= 2 * M_PI;
			while (a - t.back() < -M_PI) a += 2 * M_PI;
		}
		t.push_back(a);
	}
	double t1 = *std::min_element(t.begin(), t.end()), t2 = *std::max_element(t.begin(), t.end());
	if (t2 - t1 > 2 * M_PI - 0.15) t2 = t1 + 2 * M_PI;
	const double shift = 2 * M_PI * std::floor((t1 + M_PI) / (2 * M_PI));
	return {t1 - shift, t2 - shift};
}

/** Does the projection of conic @p c pass within 1.5 px of at least half the points? */
bool coversInImage(const ConicFit3& c, const std::vector<cv::Point2d>& q, const Rectifier& rect)
{
	std::vector<cv::Point2d> s;
	const int n = 1440;
	for (int k = 0; k <= n; ++k)
	{
		const Eigen::Vector3d x = c.pointAt(c.t1 + (c.t2 - c.t1) * k / n);
		if (x.z() <= 0) return false;
		s.push_back(rect.leftPixelOf(x));
	}
	size_t near = 0;
	for (const auto& x : q)
		for (const auto& y : s)
			if (cv::norm(x - y) <= 1.5)
			{
				++near;
				break;
			}
	return 2 * near >= q.size();
}

/** Do consecutive line pieces a, b of one string follow each other (at most 3 edgels apart) and
 * turn by less than max_turn_deg, as the chords of a flat image ellipse do? */
bool chordsJoin(const ImagePiece& a, const ImagePiece& b, double max_turn_deg)
{
	const cv::Point2d u = a.b - a.a, v = b.b - b.a;
	return b.lo <= a.hi + 3 &&
	       std::abs(u.dot(v)) >= std::cos(max_turn_deg * M_PI / 180) * cv::norm(u) * cv::norm(v);
}

/** The piece's matched edgels; those where the edge crosses the scanlines (tangent at least 30°
 * from them) if there are enough of them. */
std::vector<StereoEdgel> arcDepths(const std::vector<EdgeString>& strings, const ImagePiece& p,
                                   const std::map<std::pair<int, int>, const EdgeMatch*>& m,
                                   const Rectifier& rect, int min_matches)
{
	std::vector<StereoEdgel> all, steep;
	for (size_t i = p.lo; i < p.hi; ++i)
	{
		const auto it = m.find({p.string, static_cast<int>(i)});
		if (it == m.end()) continue;
		const EdgeMatch& x = *it->second;
		const StereoEdgel e{{x.x_left_px, x.y_px},
		                    x.disparity_px,
		                    rect.pointInLeftCamera(x.x_left_px, x.y_px, x.disparity_px)};
		all.push_back(e);
		const cv::Point2d g = strings[p.string][i].grad;  // the tangent is g turned by 90°
		if (std::abs(g.x) >= 0.5 * cv::norm(g)) steep.push_back(e);
	}
	return static_cast<int>(steep.size()) >= min_matches ? steep : all;
}

/** Leftmost and rightmost columns of the circle's projection in the left and the right rectified
 * image (the right image column is x_left − disparity). */
struct Extremes
{
	double l_min = 1e300, l_max = -1e300, r_min = 1e300, r_max = -1e300;
};
Extremes circleExtremes(const ConicFit3& c, const Rectifier& rect, double scale)
{
	Extremes e;
	for (int k = 0; k < 720; ++k)
	{
		const Eigen::Vector3d p = scale * c.pointAt(2 * M_PI * k / 720);
		const cv::Point2d q = rect.leftPixelOf(p);
		const double xr = q.x - rect.disparityOf(p);
		e.l_min = std::min(e.l_min, q.x), e.l_max = std::max(e.l_max, q.x);
		e.r_min = std::min(e.r_min, xr), e.r_max = std::max(e.r_max, xr);
	}
	return e;
}
}  // namespace

std::optional<double> rightExtremeScale(const ConicFit3& c, const std::vector<cv::Point2d>& arc_px,
                                        const std::vector<EdgeString>& right, const Rectifier& rect)
{
	const Extremes e = circleExtremes(c, rect, 1);
	double a_min = 1e300, a_max = -1e300, top = 1e300, bottom = -1e300;
	for (const auto& q : arc_px)
		a_min = std::min(a_min, q.x), a_max = std::max(a_max, q.x), top = std::min(top, q.y),
		bottom = std::max(bottom, q.y);
	// an extreme counts only where the left arc reaches it
	const double w = rect.rectifiedSize().width, m = 5;  // an arc cut by the image edge: no extreme
	bool use_min = std::abs(a_min - e.l_min) <= 1 && a_min >= m,
	     use_max = std::abs(a_max - e.l_max) <= 1 && a_max <= w - m;
	if (!use_min && !use_max) return std::nullopt;
	double r_min = 1e300, r_max = -1e300;  // the right edgels' extremes near the predicted ones
	for (const auto& s : right)
		for (const auto& x : s)
		{
			if (x.p.y < top - 1 || x.p.y > bottom + 1) continue;
			if (std::abs(x.p.x - e.r_min) <= 4) r_min = std::min(r_min, x.p.x);
			if (std::abs(x.p.x - e.r_max) <= 4) r_max = std::max(r_max, x.p.x);
		}
	use_min = use_min && r_min >= m && r_min < 1e299;
	use_max = use_max && r_max <= w - m && r_max > -1e299;
	if (!use_min && !use_max) return std::nullopt;
	// observed disparity of the extremes (same estimator in both images) minus the prediction,
	// which falls as the circle is scaled away from the camera: bisection on the scale
	auto excess = [&](double s)
	{
		const Extremes p = circleExtremes(c, rect, s);
		double sum = 0;
		if (use_min) sum += (a_min - r_min) - (p.l_min - p.r_min);
		if (use_max) sum += (a_max - r_max) - (p.l_max - p.r_max);
		return sum;
	};
	double lo = 0.9, hi = 1.1;
	if (excess(lo) > 0 || excess(hi) < 0) return std::nullopt;  // outside ±10 %
	for (int it = 0; it < 40; ++it)
	{
		const double mid = 0.5 * (lo + hi);
		(excess(mid) > 0 ? hi : lo) = mid;
	}
	return 0.5 * (lo + hi);
}

double planeSectionAxisRatio(const cv::RotatedRect& el, const Eigen::Vector3d& up_L,
                             const Rectifier& rect)
{
	const Eigen::Vector3d n = up_L.normalized();
	const auto [e1, e2] = planeBasis(n);
	const double th = el.angle * M_PI / 180;
	const cv::Point2d u(std::cos(th), std::sin(th)), v(-std::sin(th), std::cos(th));
	std::vector<cv::Point2f> uv;
	double side = 0;
	for (int k = 0; k < 180; ++k)
	{
		const double f = 2 * M_PI * k / 180;
		const cv::Point2d q = cv::Point2d(el.center) + el.size.width / 2 * std::cos(f) * u +
		                      el.size.height / 2 * std::sin(f) * v;
		const double s = n.dot(rect.leftRay(q.x, q.y));
		if (k == 0) side = s;
		if (s * side <= 1e-9) return std::numeric_limits<double>::infinity();
		const auto X = onPlane(rect, n, side > 0 ? 1000.0 : -1000.0, q);
		if (!X) return std::numeric_limits<double>::infinity();
		uv.emplace_back(static_cast<float>(X->dot(e1)), static_cast<float>(X->dot(e2)));
	}
	const cv::RotatedRect c = cv::fitEllipseDirect(uv);
	const double a = std::max(c.size.width, c.size.height),
	             b = std::min(c.size.width, c.size.height);
	return b > 0 ? a / b : std::numeric_limits<double>::infinity();
}

std::optional<ConicFit3> horizontalCircle(const std::vector<cv::Point2d>& arc_px,
                                          const std::vector<StereoEdgel>& depth,
                                          const std::optional<cv::RotatedRect>& ellipse,
                                          const Eigen::Vector3d& up_L, const Rectifier& rect,
                                          const HorizontalCircleOptions& o)
{
	if (static_cast<int>(depth.size()) < o.min_depth_matches || arc_px.size() < 5)
		return std::nullopt;
	const Eigen::Vector3d n = up_L.normalized();
	if (ellipse && planeSectionAxisRatio(*ellipse, n, rect) > o.max_axis_ratio) return std::nullopt;
	std::vector<double> hs;
	for (const auto& e : depth) hs.push_back(n.dot(e.p_L_mm));
	const double h = median(hs);
	const auto [e1, e2] = planeBasis(n);
	std::vector<Eigen::Vector3d> P;
	std::vector<Eigen::Vector2d> p;
	for (const auto& q : arc_px)
	{
		const auto X = onPlane(rect, n, h, q);
		if (!X) return std::nullopt;
		P.push_back(*X);
		p.emplace_back(X->dot(e1), X->dot(e2));
	}
	const Circle2 c = weightedCircle(P, p, e1, e2, rect);
	if (!(c.r >= o.min_radius_mm && c.r <= o.max_radius_mm)) return std::nullopt;
	const auto [t1, t2] = arcOf(p, c);
	if (t2 - t1 < o.min_arc_deg * M_PI / 180) return std::nullopt;
	ConicFit3 out;
	out.centre = c.c.x() * e1 + c.c.y() * e2 + h * n;
	const double rms_px = imageRms(arc_px, out.centre, e1, e2, c.r, rect);
	if (rms_px > o.max_residual_px) return std::nullopt;
	// e2 = n × e1: with normal n and major e1 the parameters are those of (u, v) above
	out.normal = n;
	out.major = e1;
	out.a = out.b = c.r;
	out.t1 = t1;
	out.t2 = t2;
	if (out.centre.dot(n) > 0)  // face the camera: flip the normal and the second axis's sense
	{
		out.normal = -n;
		out.t1 = -t2;
		out.t2 = -t1;
	}
	out.rms_mm = rms_px * out.centre.norm() / rect.focal_px();
	out.edgels = static_cast<int>(arc_px.size());
	return out;
}

std::vector<ConicFit3> horizontalCircles(const std::vector<EdgeString>& left_strings,
                                         const std::vector<ImagePiece>& left_pieces,
                                         const std::vector<EdgeMatch>& matches,
                                         const std::vector<ConicFit3>& existing,
                                         const Eigen::Vector3d& up_L, const Rectifier& rect,
                                         const HorizontalCircleOptions& o,
                                         const std::vector<EdgeString>* right_strings)
{
	std::map<std::pair<int, int>, const EdgeMatch*> m;
	for (const auto& x : matches) m[{x.string, x.edgel}] = &x;
	std::vector<ConicFit3> out;
	auto tryArc = [&](const ImagePiece& p, const std::optional<cv::RotatedRect>& el, double min_arc)
	{
		const auto arc = piecePoints(left_strings, p);
		const bool covered =
		    std::any_of(existing.begin(), existing.end(),
		                [&](const ConicFit3& c) { return coversInImage(c, arc, rect); });
		const auto depth = arcDepths(left_strings, p, m, rect, o.min_depth_matches);
		if (covered) return false;
		HorizontalCircleOptions oo = o;
		oo.min_arc_deg = min_arc;
		auto c = horizontalCircle(arc, depth, el, up_L, rect, oo);
		if (c && right_strings && o.right_extremes)
			if (const auto k = rightExtremeScale(*c, arc, *right_strings, rect))
				c->centre *= *k, c->a *= *k, c->b *= *k, c->rms_mm *= *k;
		if (c) out.push_back(*c);
		return c.has_value();
	};
	for (const auto& p : left_pieces)
		if (!p.is_line) tryArc(p, p.ellipse, o.min_arc_deg);
	// runs of line pieces turning smoothly: a flat rim's chords that no ellipse fit joined
	for (size_t i = 0; i < left_pieces.size();)
	{
		size_t j = i + 1;
		while (j < left_pieces.size() && left_pieces[i].is_line && left_pieces[j].is_line &&
		       left_pieces[j].string == left_pieces[i].string &&
		       chordsJoin(left_pieces[j - 1], left_pieces[j], o.max_chord_turn_deg))
			++j;
		if (j - i >= 2)
		{
			ImagePiece run = left_pieces[i];
			run.hi = left_pieces[j - 1].hi;
			tryArc(run, std::nullopt, o.min_run_arc_deg);
		}
		i = j;
	}
	return out;
}

}  // namespace mrolr::stereo
