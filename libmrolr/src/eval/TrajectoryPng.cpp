// trajectory.png: the run seen from above.
#include <mrolr/eval/MissionOutputs.h>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>

namespace mrolr::eval
{
namespace
{
using mission::PathSample;

struct TopView
{
	double scale = 100;  ///< pixels per metre
	Eigen::Vector3d lo, hi;
	cv::Point px(double z, double x) const
	{
		return {static_cast<int>((hi.x() - x) * scale), static_cast<int>((hi.z() - z) * scale)};
	}
};

/** The room with truth; else the plan's and the run's extent with a margin. */
TopView viewOf(const mission::MissionResult& r, const mission::MissionOptions& o,
               const MissionTruth* truth)
{
	TopView v;
	if (truth && truth->world && truth->world->has_room)
	{
		v.lo = truth->world->room.min_m, v.hi = truth->world->room.max_m;
		return v;
	}
	v.lo = Eigen::Vector3d::Constant(1e9), v.hi = -v.lo;
	auto add = [&](double z, double x)
	{
		v.lo = v.lo.cwiseMin(Eigen::Vector3d(x, 0, z)), v.hi = v.hi.cwiseMax(Eigen::Vector3d(x, 0, z));
	};
	for (const auto& w : o.plan.waypoints) add(w.xv_zxphi.x(), w.xv_zxphi.y());
	for (const auto& s : r.path) add(s.estimate.x(), s.estimate.y());
	for (const auto& m : r.map) add(m.p_FinW.z(), m.p_FinW.x());
	v.lo -= Eigen::Vector3d::Constant(1.0), v.hi += Eigen::Vector3d::Constant(1.0);
	return v;
}

void drawLine(cv::Mat& img, const TopView& v, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
              const cv::Scalar& colour)
{
	cv::line(img, v.px(a.x(), a.y()), v.px(b.x(), b.y()), colour, 2, cv::LINE_AA);
}

void drawPath(cv::Mat& img, const TopView& v, const std::vector<PathSample>& path,
              Eigen::Vector3d PathSample::*field, const cv::Scalar& colour)
{
	for (size_t i = 1; i < path.size(); ++i)
		drawLine(img, v, path[i - 1].*field, path[i].*field, colour);
}

/** A footprint centred at (z, x) in W, turned by yaw, @p depth along its z, @p length along x. */
void drawFootprint(cv::Mat& img, const TopView& v, double z, double x, double yaw_deg, double depth,
                   double length, const cv::Scalar& colour)
{
	const double yaw = yaw_deg * M_PI / 180.0;
	const Eigen::Vector2d az(std::cos(yaw), std::sin(yaw)), ax(-std::sin(yaw), std::cos(yaw));
	std::vector<cv::Point> pts;
	for (auto [sz, sx] : {std::pair{-1, -1}, {-1, 1}, {1, 1}, {1, -1}})
	{
		const Eigen::Vector2d c =
		    Eigen::Vector2d(z, x) + 0.5 * (sz * depth * az + sx * length * ax);
		pts.push_back(v.px(c.x(), c.y()));
	}
	cv::fillConvexPoly(img, pts, colour);
}

void drawTruth(cv::Mat& img, const TopView& v, const MissionTruth& t)
{
	if (t.world)
	{
		for (const auto& ob : t.world->obstacles)
			drawFootprint(img, v, ob.z_m, ob.x_m, ob.yaw_deg, ob.size_m.z(), ob.size_m.x(),
			              {60, 110, 160});
		for (const auto& l : t.world->landmarks)
			cv::drawMarker(img, v.px(l.p_LinW.z(), l.p_LinW.x()), {0, 0, 0}, cv::MARKER_SQUARE, 8, 2);
	}
	for (size_t i = 1; i < t.steps.size(); ++i)
		drawLine(img, v, t.steps[i - 1].xv_zxphi, t.steps[i].xv_zxphi, {0, 160, 0});
	for (const auto& o : t.objects)
		cv::circle(img, v.px(o.T_OinW.translation().z(), o.T_OinW.translation().x()), 4,
		           {0, 140, 255}, -1);
	if (t.contact)
		cv::drawMarker(img, v.px(t.contact->p_zx.x(), t.contact->p_zx.y()), {0, 0, 0},
		               cv::MARKER_TILTED_CROSS, 24, 3);
}

void drawLegend(cv::Mat& img, bool truth)
{
	std::vector<std::pair<const char*, cv::Scalar>> items = {{"estimate", {200, 0, 0}},
	                                                         {"dead reckoning", {0, 0, 220}},
	                                                         {"landmark (mapped)", {200, 0, 200}},
	                                                         {"table (plan)", {90, 90, 90}}};
	if (truth)
		items.insert(items.begin(), {{"true path", {0, 160, 0}}, {"landmark (true)", {0, 0, 0}}});
	int y = 20;
	for (const auto& [text, colour] : items)
	{
		cv::putText(img, text, {10, y}, cv::FONT_HERSHEY_SIMPLEX, 0.5, colour, 1, cv::LINE_AA);
		y += 20;
	}
}
}  // namespace

void writeTrajectoryPng(const mission::MissionResult& r, const mission::MissionOptions& o,
                        const MissionTruth* truth, const std::string& path)
{
	const TopView v = viewOf(r, o, truth);
	cv::Mat img(std::max(1, static_cast<int>((v.hi.z() - v.lo.z()) * v.scale)),
	            std::max(1, static_cast<int>((v.hi.x() - v.lo.x()) * v.scale)), CV_8UC3,
	            cv::Scalar(255, 255, 255));
	for (const auto& t : o.plan.tables)
		drawFootprint(img, v, t.z_m, t.x_m, t.yaw_deg, t.depth_m, t.length_m, {90, 90, 90});
	for (const auto& m : r.map)
		cv::drawMarker(img, v.px(m.p_FinW.z(), m.p_FinW.x()), {200, 0, 200}, cv::MARKER_CROSS, 12,
		               2);
	drawPath(img, v, r.path, &PathSample::odometry, {0, 0, 220});
	drawPath(img, v, r.path, &PathSample::estimate, {200, 0, 0});
	if (truth) drawTruth(img, v, *truth);
	for (const auto& e : r.obstacle.events)
		for (const auto& p : e.via_zx_inW)
			cv::drawMarker(img, v.px(p.x(), p.y()), {0, 120, 255}, cv::MARKER_DIAMOND, 12, 2);
	if (r.collided)
		cv::drawMarker(img, v.px(r.collision_estimate.x(), r.collision_estimate.y()), {0, 0, 255},
		               cv::MARKER_TILTED_CROSS, 24, 3);
	drawLegend(img, truth != nullptr);
	if (!cv::imwrite(path, img)) throw std::runtime_error("cannot write " + path);
}

}  // namespace mrolr::eval
