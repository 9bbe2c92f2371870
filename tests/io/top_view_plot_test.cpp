// The one top-view plot (io/TopViewPlot.h): metric axes with a round grid, equal scale with z up
// and x to the left, the legend outside the data, and 95 % ellipses of the right size.
#include <mrolr/io/TopViewPlot.h>

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <random>

using namespace mrolr;
using io::TopViewPlot;

namespace
{
const io::PlotStyle kBlue{{200, 0, 0}, 2};

bool isColour(const cv::Mat& img, cv::Point p, const cv::Scalar& bgr)
{
	const auto v = img.at<cv::Vec3b>(p);
	return v[0] == bgr[0] && v[1] == bgr[1] && v[2] == bgr[2];
}
}  // namespace

TEST(TopViewPlot, GridStepIsRoundAndGivesFourToTenIntervals)
{
	std::mt19937 rng(3);
	std::uniform_real_distribution<double> log_span(-3, 4);
	for (int i = 0; i < 2000; ++i)
	{
		const double span = std::pow(10.0, log_span(rng));
		const double step = io::gridStep(span);
		const double mantissa = step / std::pow(10.0, std::floor(std::log10(step) + 1e-12));
		EXPECT_TRUE(std::abs(mantissa - 1) < 1e-9 || std::abs(mantissa - 2) < 1e-9 ||
		            std::abs(mantissa - 5) < 1e-9)
		    << span << " -> " << step;
		EXPECT_GE(span / step, 4 - 1e-9) << span;
		EXPECT_LE(span / step, 10 + 1e-9) << span;
	}
	EXPECT_THROW(io::gridStep(0), std::invalid_argument);
	EXPECT_THROW(io::gridStep(NAN), std::invalid_argument);
}

TEST(TopViewPlot, EqualScaleWithZUpAndXToTheLeft)
{
	TopViewPlot plot("t");
	plot.addPath("path", {{-1, 2}, {3, -0.5}}, kBlue);
	const auto f = plot.layout(600);
	const Eigen::Vector2d p(0.3, 0.7);
	const auto a = f.toPixel(p);
	const auto up = f.toPixel(p + Eigen::Vector2d(1, 0));
	const auto left = f.toPixel(p + Eigen::Vector2d(0, 1));
	EXPECT_NEAR(a.y - up.y, f.px_per_m, 1e-9);  // one metre of z: px_per_m rows up
	EXPECT_NEAR(up.x, a.x, 1e-9);
	EXPECT_NEAR(a.x - left.x, f.px_per_m, 1e-9);  // one metre of x: px_per_m columns left
	EXPECT_NEAR(left.y, a.y, 1e-9);
	EXPECT_NEAR(std::max(f.data_px.width, f.data_px.height), 600, 1);
}

TEST(TopViewPlot, EverythingIsInsideTheDataAndTheLegendIsOutside)
{
	std::mt19937 rng(7);
	std::normal_distribution<double> n(0, 5);
	for (int trial = 0; trial < 50; ++trial)
	{
		TopViewPlot plot("trial");
		std::vector<Eigen::Vector2d> pts, centres;
		std::vector<Eigen::Matrix2d> P;
		for (int i = 0; i < 20; ++i) pts.emplace_back(n(rng), n(rng));
		for (int i = 0; i < 5; ++i)
		{
			centres.emplace_back(n(rng), n(rng));
			const double s = std::abs(n(rng)) / 10;
			P.push_back(Eigen::Matrix2d::Identity() * s * s);
		}
		plot.addPath("path", pts, kBlue);
		plot.addEllipses95("ellipses", centres, P, kBlue);
		const auto f = plot.layout(400);
		const cv::Rect2d data(f.data_px);
		for (const auto& p : pts) EXPECT_TRUE(data.contains(f.toPixel(p)));
		for (size_t i = 0; i < centres.size(); ++i)
		{
			const double r = io::ellipse95(P[i]).major_m;
			for (const Eigen::Vector2d& d : {Eigen::Vector2d(r, 0), Eigen::Vector2d(0, r)})
			{
				EXPECT_TRUE(data.contains(f.toPixel(centres[i] + d)));
				EXPECT_TRUE(data.contains(f.toPixel(centres[i] - d)));
			}
		}
		EXPECT_TRUE((f.data_px & f.legend_px).empty());
		EXPECT_GE(f.legend_px.x, f.data_px.br().x);
	}
}

TEST(TopViewPlot, Ellipse95HasTheChiSquareRadius)
{
	const double a = 0.3, sd_major = 0.2, sd_minor = 0.05;
	Eigen::Matrix2d R;
	R << std::cos(a), -std::sin(a), std::sin(a), std::cos(a);
	const Eigen::Matrix2d P =
	    R * Eigen::Vector2d(sd_major * sd_major, sd_minor * sd_minor).asDiagonal() * R.transpose();
	const auto e = io::ellipse95(P);
	EXPECT_NEAR(e.major_m, std::sqrt(io::kChi2_95_2dof) * sd_major, 1e-12);
	EXPECT_NEAR(e.minor_m, std::sqrt(io::kChi2_95_2dof) * sd_minor, 1e-12);
	EXPECT_NEAR(std::abs(e.major_axis_zx.dot(R.col(0))), 1, 1e-12);
	// a landmark's (z, x) marginal of W's (x, y, z) covariance
	Eigen::Matrix3d P3 = Eigen::Matrix3d::Zero();
	P3(0, 0) = 4, P3(1, 1) = 9, P3(2, 2) = 1, P3(0, 2) = P3(2, 0) = 0.5;
	const Eigen::Matrix2d M = io::zxMarginalOfPoint(P3);
	EXPECT_EQ(M(0, 0), 1);
	EXPECT_EQ(M(1, 1), 4);
	EXPECT_EQ(M(0, 1), 0.5);
}

TEST(TopViewPlot, RenderedEllipseAndPathAreWhereTheirMetresSay)
{
	TopViewPlot plot("render");
	const double sd_z = 0.1;
	plot.addEllipses95("estimate", {{1, 1}}, {Eigen::Vector2d(sd_z * sd_z, 1e-6).asDiagonal()},
	                   {{0, 0, 255}, 2});
	plot.addPath("path", {{-1, -1}, {-1, 2}}, kBlue);
	const cv::Mat img = plot.render(500);
	const auto f = plot.layout(500);
	// the path: a row of blue pixels at z = −1 between its ends
	const auto mid = f.toPixel({-1, 0.5});
	EXPECT_TRUE(isColour(img, {int(std::lround(mid.x)), int(std::lround(mid.y))}, kBlue.bgr));
	// the ellipse: red pixels along its column span 2 · 2.448 σ_z
	const auto c = f.toPixel({1, 1});
	int top = img.rows, bottom = -1;
	for (int r = 0; r < img.rows; ++r)
		for (int dc = -2; dc <= 2; ++dc)
		{
			const auto v = img.at<cv::Vec3b>(r, int(std::lround(c.x)) + dc);  // red, antialiased
			if (v[2] > 150 && v[1] < 120 && v[0] < 120) top = std::min(top, r), bottom = r;
		}
	ASSERT_GE(bottom, 0);
	EXPECT_NEAR(bottom - top, 2 * std::sqrt(io::kChi2_95_2dof) * sd_z * f.px_per_m, 3);
	// the legend samples are drawn in the panel, not on the data
	int blue_in_legend = 0;
	for (int r = f.legend_px.y; r < f.legend_px.br().y; ++r)
		for (int col = f.legend_px.x; col < f.legend_px.br().x; ++col)
			blue_in_legend += isColour(img, {col, r}, kBlue.bgr);
	EXPECT_GT(blue_in_legend, 20);
	EXPECT_GT(img.cols, f.legend_px.br().x - 1);
}

TEST(TopViewPlot, BadInputIsNamed)
{
	TopViewPlot plot("bad");
	try
	{
		plot.addEllipses95("map", {{0, 0}, {1, 1}}, {Eigen::Matrix2d::Identity()}, kBlue);
		ADD_FAILURE() << "no throw";
	}
	catch (const std::invalid_argument& e)
	{
		EXPECT_NE(std::string(e.what()).find("map"), std::string::npos) << e.what();
	}
	EXPECT_THROW(plot.layout(10), std::invalid_argument);
	const std::string bad = "/nonexistent_dir_mrolr/plot.png";
	try
	{
		plot.write(bad);
		ADD_FAILURE() << "no throw";
	}
	catch (const std::exception& e)
	{
		EXPECT_NE(std::string(e.what()).find(bad), std::string::npos) << e.what();
	}
	// a non-finite point neither stretches the view nor is drawn
	TopViewPlot lost("lost");
	lost.addPath("path", {{0, 0}, {NAN, 1e9}, {1, 1}}, kBlue);
	EXPECT_LT(lost.layout(400).grid_step_m, 1.0);
	EXPECT_NO_THROW(lost.render(400));
}
