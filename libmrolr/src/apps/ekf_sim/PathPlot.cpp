#include "SimulationOutputs.h"

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include <Eigen/Eigenvalues>

#include <stdexcept>

namespace mrolr::apps::detail
{
namespace
{
constexpr int kSize = 900, kMargin = 40;
constexpr double kChi2_95_2dof = 5.991464547;

/** Maps W's (z, x) to pixels: z up, x to the left, equal scale. */
struct View
{
	double z0 = 0, x0 = 0, scale = 1;
	cv::Point2d px(double z, double x) const
	{
		return {kMargin + (x0 - x) * scale, kMargin + (z0 - z) * scale};
	}
};

View fit(const world::World& w, const eval::RunResult& run)
{
	double zmin = 1e9, zmax = -1e9, xmin = 1e9, xmax = -1e9;
	const auto add = [&](double z, double x)
	{
		zmin = std::min(zmin, z), zmax = std::max(zmax, z), xmin = std::min(xmin, x),
		xmax = std::max(xmax, x);
	};
	for (const auto& l : w.landmarks) add(l.p_LinW.z(), l.p_LinW.x());
	for (const auto& s : run.steps)
		add(s.truth[0], s.truth[1]), add(s.estimate[0], s.estimate[1]),
		    add(s.dead_reckoning[0], s.dead_reckoning[1]);
	View v;
	v.z0 = zmax;
	v.x0 = xmax;
	v.scale = (kSize - 2 * kMargin) / std::max({zmax - zmin, xmax - xmin, 1e-3});
	return v;
}

/** 95 % ellipse of the (z, x) covariance C centred at (z, x). */
void drawEllipse(cv::Mat& img, const View& v, double z, double x, const Eigen::Matrix2d& C,
                 const cv::Scalar& colour)
{
	Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> e(C);
	const Eigen::Vector2d l = e.eigenvalues().cwiseMax(0);
	const Eigen::Vector2d d = e.eigenvectors().col(1);  // major axis in (z, x)
	// In the image, z is −row and x is −column: the axis (dz, dx) points to (−dx, −dz) in pixels.
	const double angle = std::atan2(-d[0], -d[1]) * 180 / M_PI;
	const cv::Size2d axes(std::sqrt(kChi2_95_2dof * l[1]) * v.scale,
	                      std::sqrt(kChi2_95_2dof * l[0]) * v.scale);
	cv::ellipse(img,
	            cv::RotatedRect(v.px(z, x), cv::Size2f(2 * axes.width, 2 * axes.height), angle),
	            colour, 1, cv::LINE_AA);
}

void drawPath(cv::Mat& img, const View& v, const eval::RunResult& run, int which,
              const cv::Scalar& colour)
{
	std::vector<cv::Point> pts;
	for (const auto& s : run.steps)
	{
		const Eigen::Vector3d& p = which == 0   ? s.truth
		                           : which == 1 ? s.estimate
		                                        : s.dead_reckoning;
		pts.push_back(v.px(p[0], p[1]));
	}
	cv::polylines(img, pts, false, colour, 2, cv::LINE_AA);
}

void drawLegend(cv::Mat& img)
{
	const std::pair<const char*, cv::Scalar> items[] = {
	    {"true path", {0, 160, 0}},
	    {"EKF-SLAM estimate (95% ellipses)", {200, 0, 0}},
	    {"dead reckoning", {0, 0, 220}},
	    {"landmarks (filled: known), mapped features", {0, 0, 0}}};
	int y = 20;
	for (const auto& [text, colour] : items)
	{
		cv::putText(img, text, {10, y}, cv::FONT_HERSHEY_SIMPLEX, 0.5, colour, 1, cv::LINE_AA);
		y += 18;
	}
}
}  // namespace

void writePathPlot(const std::string& png, const world::World& w, const eval::RunResult& run)
{
	cv::Mat img(kSize, kSize, CV_8UC3, cv::Scalar(255, 255, 255));
	const View v = fit(w, run);
	for (const auto& l : w.landmarks)
		cv::rectangle(img, v.px(l.p_LinW.z(), l.p_LinW.x()) - cv::Point2d(4, 4),
		              v.px(l.p_LinW.z(), l.p_LinW.x()) + cv::Point2d(4, 4), {0, 0, 0},
		              l.known ? cv::FILLED : 1);
	for (size_t i = 0; i < run.final_positions.size(); ++i)
	{
		const auto& p = run.final_positions[i];
		const auto& C = run.final_covariances[i];
		Eigen::Matrix2d Czx;
		Czx << C(2, 2), C(2, 0), C(0, 2), C(0, 0);
		cv::circle(img, v.px(p.z(), p.x()), 3, {200, 0, 0}, cv::FILLED);
		drawEllipse(img, v, p.z(), p.x(), Czx, {200, 0, 0});
	}
	drawPath(img, v, run, 2, {0, 0, 220});
	drawPath(img, v, run, 0, {0, 160, 0});
	drawPath(img, v, run, 1, {200, 0, 0});
	for (size_t k = 0; k < run.steps.size(); k += 5)
		drawEllipse(img, v, run.steps[k].estimate[0], run.steps[k].estimate[1],
		            run.steps[k].P_vv.topLeftCorner<2, 2>(), {200, 0, 0});
	drawLegend(img);
	if (!cv::imwrite(png, img)) throw std::runtime_error("cannot write '" + png + "'");
}

}  // namespace mrolr::apps::detail
