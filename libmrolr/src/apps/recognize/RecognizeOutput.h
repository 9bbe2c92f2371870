#pragma once
/** Outputs of mrolr-recognize: JSON records, the overlay on the left image and the 3D scene. */

#include <mrolr/model/WireFrame.h>
#include <mrolr/recog/Recognizer.h>
#include <mrolr/stereo/StereoCalibration.h>

#include <nlohmann/json.hpp>
#include <opencv2/core.hpp>

#include <string>
#include <vector>

namespace mrolr::apps
{
/** Roll, pitch, yaw (deg) of R = Rz(yaw) Ry(pitch) Rx(roll). */
Eigen::Vector3d rollPitchYawDeg(const Eigen::Matrix3d& R);

/** {"cliques", "verify_3d", "image_score", "image_refine", "plane"}: ms of each stage. */
nlohmann::json timesJson(const recog::RecognitionTimes& t);

/** {"model", "found", "T", "score", "matched", "level", "ms", "times_ms", "confidence", "scene",
 * "rpy_deg", "t_mm", "agreeing_cliques", "spread_rot_deg", "spread_trans_mm", "image_score",
 * "origin", "occluders", "ambiguous", "poses"}; level, scene and image_score null when absent. */
nlohmann::json resultJson(const recog::RecognitionResult& r);

/** Points along a wire-frame's lines and arcs (mm, its own frame), as polylines. */
std::vector<std::vector<Eigen::Vector3d>> polylinesOf(const model::WireFrame& wf);

/** Draws the first scene (grey) and every found model carried into it (one colour each, with its
 * name) on @p left (thesis L frame is OpenCV's camera frame turned 180° about z; the image is the
 * unrectified left image, so the calibration's K_left and D_left project). */
void writeOverlay(cv::Mat left, const stereo::StereoCalibration& calib,
                  const std::vector<model::WireFrame>& scenes,
                  const std::vector<model::WireFrame>& models,
                  const std::vector<recog::RecognitionResult>& results, const std::string& png);

/** MRPT .3Dscene: every scene model (grey lines) and the found models carried into their scene
 * (coloured), coordinates converted from mm to m. */
void writeScene3D(const std::vector<model::WireFrame>& scenes,
                  const std::vector<model::WireFrame>& models,
                  const std::vector<recog::RecognitionResult>& results, const std::string& path);

}  // namespace mrolr::apps
