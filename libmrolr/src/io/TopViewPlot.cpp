// The items of a top view and its layout (TopViewPlot.h); the drawing is in TopViewDrawing.cpp.
#include <mrolr/io/TopViewPlot.h>

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace mrolr::io
{
namespace
{
constexpr int kLeftMarginPx = 80, kTopMarginPx = 56, kLegendGapPx = 24, kLegendWidthPx = 300;
constexpr double kMinSpan_m = 0.5;     // the smallest view: a point still gets a readable grid
constexpr double kMarginFraction = 0.06;  // room around the data, of its larger span
}  // namespace

Ellipse95 ellipse95(const Eigen::Matrix2d& P_zx)
{
	const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> e(0.5 * (P_zx + P_zx.transpose()));
	const Eigen::Vector2d l = e.eigenvalues().cwiseMax(0.0);  // ascending
	Ellipse95 out;
	out.major_m = std::sqrt(kChi2_95_2dof * l[1]);
	out.minor_m = std::sqrt(kChi2_95_2dof * l[0]);
	out.major_axis_zx = e.eigenvectors().col(1);
	return out;
}

Eigen::Matrix2d zxBlockOfVehicle(const Eigen::Matrix3d& P_vv)
{
	return P_vv.topLeftCorner<2, 2>();
}

Eigen::Matrix2d zxMarginalOfPoint(const Eigen::Matrix3d& P_xyz)
{
	Eigen::Matrix2d P;
	P << P_xyz(2, 2), P_xyz(2, 0), P_xyz(0, 2), P_xyz(0, 0);
	return P;
}

cv::Point2d PlotFrame::toPixel(const Eigen::Vector2d& zx) const
{
	return {data_px.x + (x_left_m - zx.y()) * px_per_m, data_px.y + (z_top_m - zx.x()) * px_per_m};
}

double gridStep(double span_m)
{
	if (!(span_m > 0) || !std::isfinite(span_m))
		throw std::invalid_argument("gridStep: span must be positive and finite");
	const double decade = std::pow(10.0, std::floor(std::log10(span_m / 10)));
	for (const double m : {1.0, 2.0, 5.0, 10.0})
		if (span_m / (m * decade) <= 10) return m * decade;
	return 10 * decade;
}

TopViewPlot::TopViewPlot(std::string title) : title_(std::move(title)) {}

void TopViewPlot::grow(const Eigen::Vector2d& zx)
{
	if (!zx.allFinite()) return;  // a lost or unset value is not drawn and does not stretch the view
	if (!has_extent_) lo_zx_ = hi_zx_ = zx;
	lo_zx_ = lo_zx_.cwiseMin(zx), hi_zx_ = hi_zx_.cwiseMax(zx);
	has_extent_ = true;
}

void TopViewPlot::addPath(const std::string& label, const std::vector<Eigen::Vector2d>& zx,
                          const PlotStyle& style)
{
	for (const auto& p : zx) grow(p);
	items_.push_back({Item::Kind::Path, label, style, Marker::Cross, 0, {zx}, {}});
}

void TopViewPlot::addPoints(const std::string& label, const std::vector<Eigen::Vector2d>& zx,
                            Marker marker, const PlotStyle& style, int size_px)
{
	for (const auto& p : zx) grow(p);
	items_.push_back({Item::Kind::Points, label, style, marker, size_px, {zx}, {}});
}

void TopViewPlot::addEllipses95(const std::string& label,
                                const std::vector<Eigen::Vector2d>& centres_zx,
                                const std::vector<Eigen::Matrix2d>& P_zx, const PlotStyle& style,
                                size_t at_most)
{
	if (centres_zx.size() != P_zx.size())
		throw std::invalid_argument("TopViewPlot::addEllipses95 '" + label + "': " +
		                            std::to_string(centres_zx.size()) + " centres but " +
		                            std::to_string(P_zx.size()) + " covariances");
	const size_t every = at_most > 0 ? std::max<size_t>(1, centres_zx.size() / at_most) : 1;
	std::vector<Eigen::Vector2d> centres;
	std::vector<Eigen::Matrix2d> P;
	for (size_t i = 0; i < centres_zx.size(); i += every)
	{
		const double r = ellipse95(P_zx[i]).major_m;
		grow(centres_zx[i] - Eigen::Vector2d::Constant(r));
		grow(centres_zx[i] + Eigen::Vector2d::Constant(r));
		centres.push_back(centres_zx[i]), P.push_back(P_zx[i]);
	}
	items_.push_back({Item::Kind::Ellipses, label, style, Marker::Cross, 0, {centres}, P});
}

void TopViewPlot::addPolygons(const std::string& label,
                              const std::vector<std::vector<Eigen::Vector2d>>& polygons_zx,
                              const PlotStyle& style)
{
	for (const auto& poly : polygons_zx)
		for (const auto& p : poly) grow(p);
	items_.push_back({Item::Kind::Polygons, label, style, Marker::Cross, 0, polygons_zx, {}});
}

void TopViewPlot::includeExtent(const Eigen::Vector2d& lo_zx, const Eigen::Vector2d& hi_zx)
{
	grow(lo_zx);
	grow(hi_zx);
}

std::vector<Eigen::Vector2d> TopViewPlot::rectangle(const Eigen::Vector2d& centre_zx,
                                                    double yaw_rad, double depth_m,
                                                    double length_m)
{
	const Eigen::Vector2d az(std::cos(yaw_rad), std::sin(yaw_rad));
	const Eigen::Vector2d ax(-std::sin(yaw_rad), std::cos(yaw_rad));
	std::vector<Eigen::Vector2d> out;
	for (const auto& [sz, sx] : {std::pair{-1, -1}, {-1, 1}, {1, 1}, {1, -1}})
		out.push_back(centre_zx + 0.5 * (sz * depth_m * az + sx * length_m * ax));
	return out;
}

PlotFrame TopViewPlot::layout(int data_size_px) const
{
	if (data_size_px < 100)
		throw std::invalid_argument("TopViewPlot: data_size_px must be at least 100, not " +
		                            std::to_string(data_size_px));
	Eigen::Vector2d lo = has_extent_ ? lo_zx_ : Eigen::Vector2d::Zero();
	Eigen::Vector2d hi = has_extent_ ? hi_zx_ : Eigen::Vector2d::Zero();
	const Eigen::Vector2d mid = 0.5 * (lo + hi);
	Eigen::Vector2d half = (0.5 * (hi - lo)).cwiseMax(0.5 * kMinSpan_m);
	half += Eigen::Vector2d::Constant(kMarginFraction * 2 * half.maxCoeff());
	lo = mid - half, hi = mid + half;
	PlotFrame f;
	f.px_per_m = data_size_px / (2 * half.maxCoeff());
	f.z_top_m = hi.x();
	f.x_left_m = hi.y();
	f.data_px = cv::Rect(kLeftMarginPx, kTopMarginPx, int(std::lround(2 * half.y() * f.px_per_m)),
	                     int(std::lround(2 * half.x() * f.px_per_m)));
	f.grid_step_m = gridStep(2 * half.maxCoeff());
	f.legend_px = cv::Rect(f.data_px.br().x + kLegendGapPx, f.data_px.y, kLegendWidthPx,
	                       std::max(f.data_px.height, 40));
	return f;
}

}  // namespace mrolr::io
