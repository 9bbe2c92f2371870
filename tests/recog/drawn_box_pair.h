#pragma once
/** The image-verification tests' scene: the stapler box of sim::makeStaplerBox() drawn into the
 * synthetic stereo rig (synthetic_rig.h) at boxPose(), its visible faces filled in different
 * greys, with the slot and the round button on top; Pair holds its features, self-occlusion and
 * the ImageVerifier of the drawn pair. */
#include "synthetic_rig.h"

#include <mrolr/recog/SelfOcclusion.h>
#include <mrolr/recog/images/ImageVerifier.h>
#include <mrolr/sim/SyntheticObjects.h>

#include <opencv2/imgproc.hpp>

#include <cmath>
#include <vector>

namespace mrolr::recog::test
{
inline void fillPolygon(cv::Mat& img, const std::vector<Eigen::Vector3d>& p_L, double cam_x_cv_mm,
                        int grey)
{
	std::vector<cv::Point> px;
	for (const auto& p : p_L)
	{
		const cv::Point2d q = pixel(p, cam_x_cv_mm) * 16.0;  // 4 bits of sub-pixel precision
		px.emplace_back(static_cast<int>(std::lround(q.x)), static_cast<int>(std::lround(q.y)));
	}
	cv::fillConvexPoly(img, px, cv::Scalar(grey), cv::LINE_AA, 4);
}

/** The stapler box of makeStaplerBox() rendered by one camera: its visible faces filled in
 * different greys (step edges, as a renderer gives), the slot and the round button on top. */
inline cv::Mat draw(const Eigen::Isometry3d& T_OinL, double cam_x_cv_mm)
{
	cv::Mat img(480, 640, CV_8U, cv::Scalar(20));
	const auto corner = [&](int i)
	{ return T_OinL * Eigen::Vector3d(i & 1 ? 80 : -80, i & 2 ? 22.5 : -22.5, i & 4 ? 55 : 0); };
	const int faces[6][4] = {{0, 2, 6, 4}, {1, 3, 7, 5}, {0, 1, 5, 4},
	                         {2, 3, 7, 6}, {0, 1, 3, 2}, {4, 5, 7, 6}};
	const Eigen::Vector3d camera_L(cam_x_cv_mm, 0, 0);  // L's x is the OpenCV x negated
	bool top = false;
	for (int f = 0; f < 6; ++f)
	{
		std::vector<Eigen::Vector3d> q;
		Eigen::Vector3d centre = Eigen::Vector3d::Zero();
		for (int i : faces[f]) q.push_back(corner(i)), centre += corner(i) / 4;
		const Eigen::Vector3d n =
		    T_OinL.linear() * (0.5 * (-Eigen::Vector3d::Unit(f / 2)) * (f % 2 ? -2.0 : 2.0));
		if (n.dot(camera_L - centre) <= 0) continue;
		fillPolygon(img, q, cam_x_cv_mm, 70 + 30 * f);
		top = top || f == 5;
	}
	if (!top) return img;
	std::vector<Eigen::Vector3d> slot, button;
	for (const auto& p :
	     std::vector<Eigen::Vector3d>{{-50, -5, 55}, {30, -5, 55}, {30, 5, 55}, {-50, 5, 55}})
		slot.push_back(T_OinL * p);
	for (int i = 0; i < 72; ++i)
		button.push_back(T_OinL * Eigen::Vector3d(55 + 10 * std::cos(i * M_PI / 36),
		                                          10 * std::sin(i * M_PI / 36), 55));
	fillPolygon(img, slot, cam_x_cv_mm, 30);
	fillPolygon(img, button, cam_x_cv_mm, 240);
	return img;
}

inline Eigen::Isometry3d boxPose()
{
	Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
	T.linear() = (Eigen::AngleAxisd(-1.1, Eigen::Vector3d::UnitX()) *
	              Eigen::AngleAxisd(0.6, Eigen::Vector3d::UnitZ()))
	                 .toRotationMatrix();
	T.translation() = Eigen::Vector3d(10, -30, 650);
	return T;
}

struct Pair
{
	std::vector<Feature> box = featuresOf(sim::makeStaplerBox());
	SelfOcclusion occ{box};
	ImageVerifier images{draw(boxPose(), 0), draw(boxPose(), -kBaseline_mm), calibration(),
	                     ImageVerificationOptions()};
};
}  // namespace mrolr::recog::test
