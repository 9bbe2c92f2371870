#pragma once
/** The synthetic stereo rig of the image-verification tests: two parallel 640×480 cameras,
 * f = 700 px, the right one 120 mm to the right of the left one; points in the thesis's left
 * camera frame L (x left, y up, z forward, mm). */

#include <mrolr/stereo/StereoCalibration.h>

#include <Eigen/Core>
#include <opencv2/core.hpp>

namespace mrolr::recog::test
{
constexpr double kFocal_px = 700, kBaseline_mm = 120;

/** The rig's calibration (no distortion). */
inline stereo::StereoCalibration calibration()
{
	stereo::StereoCalibration c;
	c.image_size = cv::Size(640, 480);
	c.K_left = c.K_right = cv::Matx33d(kFocal_px, 0, 320, 0, kFocal_px, 240, 0, 0, 1);
	c.t_LinR_mm = cv::Vec3d(-kBaseline_mm, 0, 0);  // right camera 120 mm to the left camera's right
	return c;
}

/** Pixel of a point of L seen by a camera of the rig: @p cam_x_cv_mm is 0 for the left camera and
 * −kBaseline_mm for the right one (the point's OpenCV x is −x_L + cam_x_cv_mm). */
inline cv::Point2d pixel(const Eigen::Vector3d& p_L, double cam_x_cv_mm)
{
	const Eigen::Vector3d c(-p_L.x() + cam_x_cv_mm, -p_L.y(), p_L.z());
	return {kFocal_px * c.x() / c.z() + 320, kFocal_px * c.y() / c.z() + 240};
}

}  // namespace mrolr::recog::test
