// Drawing a laid-out top view (TopViewPlot.h): grid and axes in metres, the items, a scale bar,
// the title and the legend panel beside the data.
#include <mrolr/io/TopViewPlot.h>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <set>
#include <stdexcept>

namespace mrolr::io
{
namespace
{
constexpr int kFont = cv::FONT_HERSHEY_SIMPLEX;
constexpr double kTextScale = 0.45;
constexpr int kBottomMarginPx = 64, kRightMarginPx = 12, kLegendRowPx = 22;
const cv::Scalar kGrid{225, 225, 225}, kAxis{60, 60, 60}, kText{30, 30, 30};

std::string metres(double v, double step_m)
{
	const int decimals = std::max(0, int(-std::floor(std::log10(step_m) + 1e-9)));
	char buf[32];
	std::snprintf(buf, sizeof buf, "%.*f", decimals, std::abs(v) < 1e-9 ? 0.0 : v);
	return buf;
}

cv::Point pt(const cv::Point2d& p)
{
	return {int(std::lround(p.x)), int(std::lround(p.y))};
}

void text(cv::Mat& img, const std::string& s, cv::Point at, double scale = kTextScale,
          const cv::Scalar& colour = kText)
{
	cv::putText(img, s, at, kFont, scale, colour, 1, cv::LINE_AA);
}

/** Grid lines at multiples of the step, with their values on the left and bottom axes. */
void drawGrid(cv::Mat& img, const PlotFrame& f)
{
	const cv::Rect& r = f.data_px;
	const double s = f.grid_step_m;
	const double z_bottom = f.z_top_m - r.height / f.px_per_m;
	const double x_right = f.x_left_m - r.width / f.px_per_m;
	for (double z = std::ceil(z_bottom / s) * s; z <= f.z_top_m + 1e-9; z += s)
	{
		const int row = int(std::lround(f.toPixel({z, f.x_left_m}).y));
		cv::line(img, {r.x, row}, {r.br().x - 1, row}, kGrid, 1);
		const auto label = metres(z, s);
		int base = 0;
		const auto size = cv::getTextSize(label, kFont, kTextScale, 1, &base);
		text(img, label, {r.x - 8 - size.width, row + size.height / 2});
	}
	for (double x = std::ceil(x_right / s) * s; x <= f.x_left_m + 1e-9; x += s)
	{
		const int col = int(std::lround(f.toPixel({f.z_top_m, x}).x));
		cv::line(img, {col, r.y}, {col, r.br().y - 1}, kGrid, 1);
		const auto label = metres(x, s);
		int base = 0;
		const auto size = cv::getTextSize(label, kFont, kTextScale, 1, &base);
		text(img, label, {col - size.width / 2, r.br().y + 8 + size.height});
	}
	cv::rectangle(img, r, kAxis, 1);
	text(img, "z [m]", {r.x - 60, r.y - 10});
	text(img, "x [m], to the left (W, seen from above)", {r.x, r.br().y + 44});
}

/** A bar one grid step long under the data's right corner, outside the data. */
void drawScaleBar(cv::Mat& img, const PlotFrame& f)
{
	const int len = int(std::lround(f.grid_step_m * f.px_per_m));
	const cv::Point right(f.data_px.br().x, f.data_px.br().y + 44);
	const cv::Point left(right.x - len, right.y);
	cv::line(img, left, right, kAxis, 3);
	cv::line(img, left + cv::Point(0, -5), left + cv::Point(0, 5), kAxis, 2);
	cv::line(img, right + cv::Point(0, -5), right + cv::Point(0, 5), kAxis, 2);
	const auto label = metres(f.grid_step_m, f.grid_step_m) + " m";
	int base = 0;
	const auto size = cv::getTextSize(label, kFont, kTextScale, 1, &base);
	text(img, label, {left.x - size.width - 8, right.y + size.height / 2});
}

void drawMarker(cv::Mat& img, cv::Point p, Marker m, const PlotStyle& s, int size)
{
	switch (m)
	{
		case Marker::Disc: cv::circle(img, p, size / 2, s.bgr, cv::FILLED, cv::LINE_AA); return;
		case Marker::FilledSquare:
			cv::rectangle(img, p - cv::Point(size / 2, size / 2), p + cv::Point(size / 2, size / 2),
			              s.bgr, cv::FILLED);
			return;
		case Marker::Square: cv::drawMarker(img, p, s.bgr, cv::MARKER_SQUARE, size, s.thickness_px); return;
		case Marker::Cross: cv::drawMarker(img, p, s.bgr, cv::MARKER_CROSS, size, s.thickness_px); return;
		case Marker::TiltedCross:
			cv::drawMarker(img, p, s.bgr, cv::MARKER_TILTED_CROSS, size, s.thickness_px);
			return;
		case Marker::Diamond: cv::drawMarker(img, p, s.bgr, cv::MARKER_DIAMOND, size, s.thickness_px); return;
		case Marker::Star: cv::drawMarker(img, p, s.bgr, cv::MARKER_STAR, size, s.thickness_px); return;
	}
}

void drawEllipse(cv::Mat& img, const PlotFrame& f, const Eigen::Vector2d& c,
                 const Eigen::Matrix2d& P, const PlotStyle& s)
{
	const Ellipse95 e = ellipse95(P);
	// z is −row and x is −column: the axis (dz, dx) points to (−dx, −dz) in pixels
	const double angle_deg = std::atan2(-e.major_axis_zx.x(), -e.major_axis_zx.y()) * 180 / M_PI;
	const cv::Size2f size(float(std::max(1.0, 2 * e.major_m * f.px_per_m)),
	                      float(std::max(1.0, 2 * e.minor_m * f.px_per_m)));
	cv::ellipse(img, cv::RotatedRect(cv::Point2f(f.toPixel(c)), size, float(angle_deg)), s.bgr,
	            std::max(1, s.thickness_px - 1), cv::LINE_AA);
}

void drawItem(cv::Mat& img, const PlotFrame& f, const TopViewPlot::Item& it)
{
	using Kind = TopViewPlot::Item::Kind;
	for (size_t k = 0; k < it.zx.size(); ++k)
	{
		std::vector<cv::Point> px;
		for (const auto& p : it.zx[k])
			if (p.allFinite()) px.push_back(pt(f.toPixel(p)));
		if (it.kind == Kind::Path && px.size() > 1)
			cv::polylines(img, px, false, it.style.bgr, it.style.thickness_px, cv::LINE_AA);
		if (it.kind == Kind::Polygons && px.size() > 2) cv::fillPoly(img, std::vector<std::vector<cv::Point>>{px}, it.style.bgr);
		if (it.kind == Kind::Points)
			for (const auto& p : px) drawMarker(img, p, it.marker, it.style, it.size_px);
		if (it.kind == Kind::Ellipses)
			for (size_t i = 0; i < it.zx[k].size(); ++i)
				if (it.zx[k][i].allFinite() && it.P_zx[i].allFinite())
					drawEllipse(img, f, it.zx[k][i], it.P_zx[i], it.style);
	}
}

bool hasData(const TopViewPlot::Item& it)
{
	return !it.label.empty() &&
	       std::any_of(it.zx.begin(), it.zx.end(), [](const auto& v) { return !v.empty(); });
}

/** One row per distinct label of an item with data, in the order the items were added; a sample
 * of how it is drawn. */
void drawLegend(cv::Mat& img, const PlotFrame& f, const std::vector<TopViewPlot::Item>& items)
{
	using Kind = TopViewPlot::Item::Kind;
	cv::rectangle(img, f.legend_px, kGrid, 1);
	std::set<std::string> seen;
	int y = f.legend_px.y + 18;
	for (const auto& it : items)
	{
		if (!hasData(it) || !seen.insert(it.label).second) continue;
		const cv::Point a(f.legend_px.x + 10, y - 5), b(f.legend_px.x + 40, y - 5);
		if (it.kind == Kind::Path) cv::line(img, a, b, it.style.bgr, it.style.thickness_px, cv::LINE_AA);
		if (it.kind == Kind::Polygons)
			cv::rectangle(img, a + cv::Point(4, -6), b + cv::Point(-4, 6), it.style.bgr, cv::FILLED);
		if (it.kind == Kind::Points) drawMarker(img, (a + b) / 2, it.marker, it.style, std::min(it.size_px, 14));
		if (it.kind == Kind::Ellipses)
			cv::ellipse(img, (a + b) / 2, {14, 6}, 0, 0, 360, it.style.bgr, 1, cv::LINE_AA);
		text(img, it.label, {f.legend_px.x + 50, y});
		y += kLegendRowPx;
	}
}
}  // namespace

cv::Mat TopViewPlot::render(int data_size_px) const
{
	PlotFrame f = layout(data_size_px);
	const int rows = int(std::count_if(items_.begin(), items_.end(), hasData));
	f.legend_px.height = std::max(f.legend_px.height, 10 + rows * kLegendRowPx);
	cv::Mat img(std::max(f.data_px.br().y + kBottomMarginPx, f.legend_px.br().y + 10),
	            f.legend_px.br().x + kRightMarginPx, CV_8UC3, cv::Scalar(255, 255, 255));
	drawGrid(img, f);
	cv::Mat data = img(f.data_px);  // items are clipped to the data area
	PlotFrame inner = f;
	inner.data_px.x = inner.data_px.y = 0;
	for (const auto& it : items_) drawItem(data, inner, it);
	cv::rectangle(img, f.data_px, kAxis, 1);
	drawScaleBar(img, f);
	text(img, title_, {f.data_px.x - 60, 28}, 0.6);
	drawLegend(img, f, items_);
	return img;
}

void TopViewPlot::write(const std::string& png_path, int data_size_px) const
{
	if (!cv::imwrite(png_path, render(data_size_px)))
		throw std::runtime_error("cannot write the plot '" + png_path + "'");
}

}  // namespace mrolr::io
