#pragma once
/** Image evidence for the turntable integration (thesis 6.1, B.2.1): the left image of a view as a
 * gradient-magnitude map and the projection of points of the object frame O into it. A fixed edge
 * of the object shows as an image edge in every view that sees it, a contour generator of a smooth
 * surface found in another view does not (TurntableBuilderSupport.h). */

#include <mrolr/model/WireFrameSampling.h>
#include <mrolr/stereo/StereoCalibration.h>

#include <Eigen/Geometry>
#include <opencv2/core.hpp>

#include <vector>

namespace mrolr::model
{
/** The left image of one turntable view, ready for edge look-ups. */
struct ViewEdges
{
	cv::Mat gradient;  ///< Sobel |∇I| (CV_32F), grey levels/px
	Eigen::Isometry3d T_OinL =
	    Eigen::Isometry3d::Identity();   ///< p_L = T_OinL · p_O (thesis L, mm)
	cv::Matx33d K = cv::Matx33d::eye();  ///< left intrinsics (px)
	cv::Vec<double, 5> D = {};           ///< left distortion
};

/** Gradient map and pose of the left image @p left_grey of a view at turntable angle @p angle_deg,
 * p_T = R_TfromL · p_L + t (@p T_LinT_mm), p_T = Rz(angle) · p_O. */
ViewEdges makeViewEdges(const cv::Mat& left_grey, const stereo::StereoCalibration& calib,
                        const Eigen::Isometry3d& T_LinT_mm, double angle_deg);

/** Share of @p samples (frame O) that project in front of the camera, inside the image, onto a
 * pixel whose 3×3 neighbourhood has a gradient of at least @p min_gradient. */
double imageEdgeShare(const std::vector<FeatureSample>& samples, const ViewEdges& view,
                      double min_gradient);

}  // namespace mrolr::model
