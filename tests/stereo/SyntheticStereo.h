#pragma once
// Test helper: renders filled planar faces (polygons and discs) known in the thesis left camera
// frame L (mm) into an exactly known stereo pair, anti-aliased by 4x supersampling, so that the
// stereo pipeline can be checked against exact geometry.

#include <mrolr/stereo/SceneReconstruction.h>
#include <mrolr/stereo/StereoCalibration.h>

#include <Eigen/Geometry>
#include <opencv2/calib3d.hpp>
#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

namespace mrolr::stereo::test
{
/** A planar face: its outline (closed polygon, mm in L) and grey level. */
struct Face
{
	std::vector<Eigen::Vector3d> outline;
	int grey = 200;
};

/** Outline of a rectangle of size w×h (mm) centred at c with in-plane axes u, v (unit). */
inline Face rectangle(const Eigen::Vector3d& c, const Eigen::Vector3d& u, const Eigen::Vector3d& v,
                      double w, double h, int grey)
{
	return {{c - w / 2 * u - h / 2 * v, c + w / 2 * u - h / 2 * v, c + w / 2 * u + h / 2 * v,
	         c - w / 2 * u + h / 2 * v},
	        grey};
}

/** A disc of radius r (mm) centred at c in the plane spanned by unit u, v, as 720 vertices. */
inline Face disc(const Eigen::Vector3d& c, const Eigen::Vector3d& u, const Eigen::Vector3d& v,
                 double r, int grey)
{
	Face f{{}, grey};
	for (int i = 0; i < 720; ++i)
	{
		const double t = 2 * M_PI * i / 720;
		f.outline.push_back(c + r * std::cos(t) * u + r * std::sin(t) * v);
	}
	return f;
}

/** A parallel-ish stereo rig: 640×480, f = 700 px, baseline 120 mm, small convergence. */
inline StereoCalibration testRig(double verge_rad = 0.02)
{
	StereoCalibration c;
	c.image_size = {640, 480};
	c.K_left = c.K_right = cv::Matx33d(700, 0, 320, 0, 700, 240, 0, 0, 1);
	cv::Matx33d R;
	cv::Rodrigues(cv::Vec3d(0, -verge_rad, 0), R);  // right camera turned towards the left one
	c.R_RfromL = R;
	c.t_LinR_mm = -(R * cv::Vec3d(120, 0, 0));
	return c;
}

/** Renders the faces into one camera given p_cam = R·p_Lcv + t: far ones first (by their first
 * vertex) or, with @p depth_sort false, in the given order. */
inline cv::Mat renderView(const std::vector<Face>& faces, const cv::Matx33d& K,
                          const cv::Matx33d& R, const cv::Vec3d& t, cv::Size size,
                          bool depth_sort = true, int background = 40)
{
	const int ss = 4;
	cv::Mat big(size.height * ss, size.width * ss, CV_8U, cv::Scalar(background));
	std::vector<std::pair<double, size_t>> order;
	for (size_t i = 0; i < faces.size(); ++i)
		order.push_back({depth_sort ? -faces[i].outline[0].z() : static_cast<double>(i), i});
	std::sort(order.begin(), order.end());
	cv::Vec3d rvec;
	cv::Rodrigues(R, rvec);
	for (const auto& [depth, i] : order)
	{
		std::vector<cv::Point3d> P;
		for (const auto& p : faces[i].outline) P.emplace_back(-p.x(), -p.y(), p.z());  // L -> cv
		std::vector<cv::Point2d> uv;
		cv::projectPoints(P, rvec, t, K, cv::noArray(), uv);
		std::vector<cv::Point> poly;
		for (const auto& q : uv)
			poly.emplace_back(cvRound((q.x + 0.5) * ss * 16 - 0.5 * 16),
			                  cvRound((q.y + 0.5) * ss * 16 - 0.5 * 16));
		cv::fillPoly(big, std::vector<std::vector<cv::Point>>{poly}, cv::Scalar(faces[i].grey),
		             cv::LINE_8, 4);
	}
	cv::Mat img;
	cv::resize(big, img, size, 0, 0, cv::INTER_AREA);
	return img;
}

/** Left and right images of the faces seen by @p rig. */
inline void renderPair(const std::vector<Face>& faces, const StereoCalibration& rig, cv::Mat& left,
                       cv::Mat& right, bool depth_sort = true)
{
	left = renderView(faces, rig.K_left, cv::Matx33d::eye(), cv::Vec3d(0, 0, 0), rig.image_size,
	                  depth_sort);
	right = renderView(faces, rig.K_right, rig.R_RfromL, rig.t_LinR_mm, rig.image_size, depth_sort);
}

/** Every step of the reconstruction at its own default, before the shipped tuning that
 * SceneOptions() applies (config/model.ini used to carry it): rectification without border, 1 px fit
 * tolerances, piece stereo's own limits, circles and edge-on rims off. The synthetic tests that
 * isolate one step start from this, so what they measure is that step. */
inline SceneOptions stepDefaults()
{
	SceneOptions o;
	o.rectify = RectifyOptions{};
	o.fit = FitOptions{};
	o.segments = SegmentStereoOptions{};
	o.circles = HorizontalCircleOptions{};
	o.edge_on_rims = EdgeOnRimOptions{};
	return o;
}

}  // namespace mrolr::stereo::test
