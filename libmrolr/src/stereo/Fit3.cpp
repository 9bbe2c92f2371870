#include <mrolr/stereo/Fit3.h>

#include <Eigen/Dense>
#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace mrolr::stereo
{
namespace
{
/** Least squares d ≈ A·x, then once more without residuals beyond 3σ (σ >= 0.25 px): a stereo
 * mismatch must not tilt a whole segment. */
Eigen::VectorXd robustSolve(const Eigen::MatrixXd& A, const Eigen::VectorXd& d)
{
	Eigen::VectorXd x = A.colPivHouseholderQr().solve(d);
	const Eigen::VectorXd r = A * x - d;
	const double sigma = std::max(0.25, std::sqrt(r.squaredNorm() / r.size()));
	std::vector<int> keep;
	for (int i = 0; i < r.size(); ++i)
		if (std::abs(r[i]) <= 3 * sigma) keep.push_back(i);
	if (keep.size() < static_cast<size_t>(A.cols()) + 2 ||
	    keep.size() == static_cast<size_t>(r.size()))
		return x;
	Eigen::MatrixXd A2(keep.size(), A.cols());
	Eigen::VectorXd d2(keep.size());
	for (size_t k = 0; k < keep.size(); ++k)
	{
		A2.row(static_cast<int>(k)) = A.row(keep[k]);
		d2[static_cast<int>(k)] = d[keep[k]];
	}
	return A2.colPivHouseholderQr().solve(d2);
}

std::vector<cv::Point2f> imagePoints(const std::vector<StereoEdgel>& e)
{
	std::vector<cv::Point2f> p;
	for (const auto& x : e)
		p.emplace_back(static_cast<float>(x.xy_px.x), static_cast<float>(x.xy_px.y));
	return p;
}

double distanceToSegment(const Eigen::Vector3d& p, const Eigen::Vector3d& a,
                         const Eigen::Vector3d& b)
{
	const Eigen::Vector3d ab = b - a;
	const double t = std::clamp((p - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
	return (a + t * ab - p).norm();
}

/** Edgel positions in the ellipse's own frame scaled to the unit circle. */
cv::Point2d ellipseFrame(const cv::RotatedRect& el, const cv::Point2d& p)
{
	const double th = el.angle * M_PI / 180, c = std::cos(th), s = std::sin(th);
	const cv::Point2d q = p - cv::Point2d(el.center);
	return {(c * q.x + s * q.y) / (el.size.width / 2), (-s * q.x + c * q.y) / (el.size.height / 2)};
}

/** Point of the image ellipse at parameter phi (rad). */
cv::Point2d ellipsePoint(const cv::RotatedRect& el, double phi)
{
	const double th = el.angle * M_PI / 180;
	const cv::Point2d u(std::cos(th), std::sin(th)), v(-std::sin(th), std::cos(th));
	return cv::Point2d(el.center) + el.size.width / 2 * std::cos(phi) * u +
	       el.size.height / 2 * std::sin(phi) * v;
}

/** Approximate distance (px) of p from the ellipse. */
double ellipseDistance(const cv::RotatedRect& el, const cv::Point2d& p)
{
	const cv::Point2d u = ellipseFrame(el, p);
	const double r = std::hypot(u.x, u.y);
	return r > 0 ? std::abs(1 - 1 / r) * cv::norm(p - cv::Point2d(el.center)) : el.size.width / 2;
}

/** Unwrapped parameter angles of ordered points; returns the span in rad. */
std::vector<double> unwrappedAngles(const std::vector<cv::Point2d>& uv)
{
	std::vector<double> t;
	for (const auto& q : uv)
	{
		double a = std::atan2(q.y, q.x);
		if (!t.empty())
			while (a - t.back() > M_PI) a -= 2 * M_PI;
		if (!t.empty())
			while (a - t.back() < -M_PI) a += 2 * M_PI;
		t.push_back(a);
	}
	return t;
}

Eigen::Vector3d onPlane(const Rectifier& rect, const Eigen::Vector3d& plane, double x, double y)
{
	return rect.pointInLeftCamera(x, y, plane[0] * x + plane[1] * y + plane[2]);
}

/** The 3D ellipse through exact 3D points of a planar conic: PCA plane, then an in-plane fit. */
ConicFit3 ellipseIn3D(const std::vector<Eigen::Vector3d>& Q)
{
	Eigen::Vector3d mean = Eigen::Vector3d::Zero();
	for (const auto& q : Q) mean += q;
	mean /= static_cast<double>(Q.size());
	Eigen::Matrix3d C = Eigen::Matrix3d::Zero();
	for (const auto& q : Q) C += (q - mean) * (q - mean).transpose();
	Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es(C);
	const Eigen::Vector3d n = es.eigenvectors().col(0), e1 = es.eigenvectors().col(2),
	                      e2 = n.cross(e1);
	std::vector<cv::Point2f> uv;
	for (const auto& q : Q)
		uv.emplace_back(static_cast<float>((q - mean).dot(e1)),
		                static_cast<float>((q - mean).dot(e2)));
	const cv::RotatedRect el = cv::fitEllipseDirect(uv);
	const double th = el.angle * M_PI / 180;
	ConicFit3 c;
	c.centre = mean + el.center.x * e1 + el.center.y * e2;
	const Eigen::Vector3d ax_w = std::cos(th) * e1 + std::sin(th) * e2;
	const bool w_major = el.size.width >= el.size.height;
	c.major = w_major ? ax_w : n.cross(ax_w);
	c.a = std::max(el.size.width, el.size.height) / 2.0;
	c.b = std::min(el.size.width, el.size.height) / 2.0;
	c.normal = c.centre.dot(n) > 0 ? Eigen::Vector3d(-n) : n;  // facing the camera
	return c;
}

double parameterOf(const ConicFit3& c, const Eigen::Vector3d& p)
{
	const Eigen::Vector3d q = p - c.centre;
	return std::atan2(q.dot(c.normal.cross(c.major)) / c.b, q.dot(c.major) / c.a);
}

void setArc(ConicFit3& c, const std::vector<Eigen::Vector3d>& P)
{
	std::vector<cv::Point2d> uv;
	for (const auto& p : P)
	{
		const double t = parameterOf(c, p);
		uv.emplace_back(std::cos(t), std::sin(t));
	}
	const auto t = unwrappedAngles(uv);
	c.t1 = *std::min_element(t.begin(), t.end());
	c.t2 = *std::max_element(t.begin(), t.end());
	if (c.t2 - c.t1 > 2 * M_PI - 0.15) c.t2 = c.t1 + 2 * M_PI;  // closed
	const double shift = 2 * M_PI * std::floor((c.t1 + M_PI) / (2 * M_PI));
	c.t1 -= shift;
	c.t2 -= shift;
}

/** RMS distance (mm) of the edgels from the arc over the inliers (within 3 median distances, at
 * least 1 mm): stereo mismatches along the scanline parts of a rim must not veto a good conic.
 * Infinity when fewer than half the edgels are inliers. */
double conicRms(const ConicFit3& c, const std::vector<StereoEdgel>& e)
{
	std::vector<Eigen::Vector3d> s;
	for (int i = 0; i < 720; ++i) s.push_back(c.pointAt(c.t1 + (c.t2 - c.t1) * i / 719.0));
	std::vector<double> d;
	for (const auto& x : e)
	{
		double best = 1e300;
		for (const auto& q : s) best = std::min(best, (q - x.p_L_mm).squaredNorm());
		d.push_back(std::sqrt(best));
	}
	std::vector<double> sorted = d;
	std::nth_element(sorted.begin(), sorted.begin() + static_cast<long>(d.size() / 2),
	                 sorted.end());
	const double limit = std::max(1.0, 3 * sorted[d.size() / 2]);
	double sum = 0;
	size_t n = 0;
	for (double x : d)
		if (x <= limit) sum += x * x, ++n;
	return 2 * n < d.size() ? std::numeric_limits<double>::infinity() : std::sqrt(sum / n);
}
}  // namespace

Eigen::Vector3d ConicFit3::pointAt(double t) const
{
	return centre + a * std::cos(t) * major + b * std::sin(t) * normal.cross(major);
}

std::optional<LineFit3> fitLine3(const std::vector<StereoEdgel>& e, const Rectifier& rect,
                                 const FitOptions& o)
{
	if (static_cast<int>(e.size()) < o.min_line_edgels) return std::nullopt;
	cv::Vec4f l;
	cv::fitLine(imagePoints(e), l, cv::DIST_L2, 0, 0.01, 0.01);
	cv::Point2d v(l[0], l[1]);
	const cv::Point2d p0(l[2], l[3]);
	if ((e.back().xy_px - e.front().xy_px).dot(v) < 0) v = -v;  // p1 first along the string
	Eigen::MatrixXd A(e.size(), 2);
	Eigen::VectorXd d(e.size());
	double smin = 1e300, smax = -1e300;
	for (size_t i = 0; i < e.size(); ++i)
	{
		const cv::Point2d q = e[i].xy_px - p0;
		if (std::abs(q.cross(v)) > o.line_tol_px) return std::nullopt;
		const double s = q.dot(v);
		smin = std::min(smin, s);
		smax = std::max(smax, s);
		A.row(static_cast<int>(i)) << s, 1.0;
		d[static_cast<int>(i)] = e[i].d_px;
	}
	const Eigen::VectorXd k = robustSolve(A, d);
	auto end = [&](double s)
	{
		const cv::Point2d q = p0 + s * v;
		return rect.pointInLeftCamera(q.x, q.y, k[0] * s + k[1]);
	};
	LineFit3 f{end(smin), end(smax), 0, static_cast<int>(e.size())};
	for (const auto& x : e) f.rms_mm += std::pow(distanceToSegment(x.p_L_mm, f.p1, f.p2), 2);
	f.rms_mm = std::sqrt(f.rms_mm / static_cast<double>(e.size()));
	if (f.rms_mm > o.max_rms_mm || (f.p2 - f.p1).norm() <= 0) return std::nullopt;
	return f;
}

std::optional<cv::RotatedRect> fitEllipse2D(const std::vector<cv::Point2d>& pts,
                                            const FitOptions& o)
{
	std::vector<cv::Point2f> p32(pts.begin(), pts.end());
	const cv::RotatedRect el = cv::fitEllipseDirect(p32);
	const double big = std::max(el.size.width, el.size.height) / 2;
	const double small = std::min(el.size.width, el.size.height) / 2;
	if (!(small > 2) || big > o.max_conic_radius_px) return std::nullopt;
	std::vector<cv::Point2d> uv;
	for (const auto& x : pts)
	{
		if (ellipseDistance(el, x) > o.conic_tol_px) return std::nullopt;
		uv.push_back(ellipseFrame(el, x));
	}
	const auto t = unwrappedAngles(uv);
	if (std::abs(t.back() - t.front()) < o.min_arc_deg * M_PI / 180) return std::nullopt;
	return el;
}

std::optional<ConicFit3> conicFromEllipse(const cv::RotatedRect& el,
                                          const std::vector<cv::Point2d>& arc_px,
                                          const std::vector<StereoEdgel>& matched,
                                          const Rectifier& rect, const FitOptions& o)
{
	if (matched.size() < 3) return std::nullopt;
	Eigen::MatrixXd A(matched.size(), 3);
	Eigen::VectorXd d(matched.size());
	for (size_t i = 0; i < matched.size(); ++i)
	{
		A.row(static_cast<int>(i)) << matched[i].xy_px.x, matched[i].xy_px.y, 1.0;
		d[static_cast<int>(i)] = matched[i].d_px;
	}
	const Eigen::Vector3d plane = robustSolve(A, d);
	std::vector<Eigen::Vector3d> Q, P;
	for (int k = 0; k < 180; ++k)
	{
		const cv::Point2d q = ellipsePoint(el, 2 * M_PI * k / 180);
		Q.push_back(onPlane(rect, plane, q.x, q.y));
	}
	for (const auto& x : arc_px) P.push_back(onPlane(rect, plane, x.x, x.y));
	ConicFit3 c = ellipseIn3D(Q);
	setArc(c, P);
	c.edgels = static_cast<int>(matched.size());
	c.rms_mm = conicRms(c, matched);
	if (c.rms_mm > o.max_rms_mm) return std::nullopt;
	return c;
}

std::optional<ConicFit3> fitConic3(const std::vector<StereoEdgel>& e, const Rectifier& rect,
                                   const FitOptions& o)
{
	if (static_cast<int>(e.size()) < o.min_conic_edgels) return std::nullopt;
	std::vector<cv::Point2d> px;
	for (const auto& x : e) px.push_back(x.xy_px);
	const auto el = fitEllipse2D(px, o);
	if (!el) return std::nullopt;
	return conicFromEllipse(*el, px, e, rect, o);
}

}  // namespace mrolr::stereo
