#pragma once
/** The visible part of an exact wire-frame in one camera view (what the quality target "scene models
 * recover 60 % of the visible edge length" counts, docs/model.md): a scene model can only recover the edges the left camera
 * sees, so the truth is clipped by a depth image of that camera (the simulator's
 * depth_left_mm.png). Each feature is sampled densely; a sample is visible when it projects
 * inside the image and the rendered depth at its pixel (or one of the 8 neighbours, so that an
 * edge on a silhouette counts) agrees with its own depth within depth_tol_mm. Runs of visible
 * samples become line pieces or conic sub-arcs of the same feature (a conic keeps its centre and
 * axes, so radius errors still compare). visibleInBothCameras clips to what both cameras see. */

#include <mrolr/model/WireFrame.h>
#include <mrolr/stereo/StereoCalibration.h>

#include <opencv2/core.hpp>

namespace mrolr::model
{
struct VisibilityOptions
{
	double step_mm = 1.0;      ///< sampling step along the features
	double depth_tol_mm = 15;  ///< rendered depth vs the sample's depth
	double min_piece_mm = 3;   ///< shorter visible runs are dropped
};

/** The parts of @p truth_L (frame left_camera, mm) seen by the left camera of @p calib (its
 * intrinsics and distortion) in the depth image @p depth_mm (CV_16U or CV_32F, mm along the optic
 * axis, 0 = nothing; the calibration's image size). Throws std::invalid_argument for a truth
 * not in left_camera or a depth image of the wrong size or type. Ids are renumbered 1, 2, …. */
WireFrame visibleWireFrame(const WireFrame& truth_L, const cv::Mat& depth_mm,
                           const stereo::StereoCalibration& calib,
                           const VisibilityOptions& options = {});

/** The parts of @p truth_L that BOTH cameras of @p calib see: a stereo pair can only reconstruct
 * an edge seen in the left and the right image. As visibleWireFrame, with the right camera's
 * depth image @p depth_right_mm (the simulator's depth_right_mm.png) checked too; a sample is
 * moved into the right camera with the calibration's R_RfromL, t_LinR_mm and projected with
 * K_right, D_right. Throws std::invalid_argument as visibleWireFrame does, naming which depth
 * image is wrong. */
WireFrame visibleInBothCameras(const WireFrame& truth_L, const cv::Mat& depth_left_mm,
                               const cv::Mat& depth_right_mm,
                               const stereo::StereoCalibration& calib,
                               const VisibilityOptions& options = {});

}  // namespace mrolr::model
