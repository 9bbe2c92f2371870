#pragma once
/** Finding one ArUco marker (OpenCV's DICT_4X4_50, cv::aruco::detectMarkers) in a grey image: the
 * image of the square's centre is where its diagonals cross, exact under perspective (the mean of
 * the four corners is not). Used to triangulate the arm's calibration marker (arm/MountCalibration.h,
 * thesis eq 6.7.2). */

#include <opencv2/core.hpp>

#include <Eigen/Core>

#include <array>
#include <optional>

namespace mrolr::stereo
{
struct ArucoSighting
{
	std::array<Eigen::Vector2d, 4> corners_px;  ///< OpenCV's order: the code's top-left first, clockwise
	Eigen::Vector2d centre_px = Eigen::Vector2d::Zero();  ///< where the diagonals cross
};

/** The marker @p id of DICT_4X4_50 in @p grey (8-bit), corners refined to sub-pixel; nothing when
 * it is not found (or found twice: an id must be unique in view). */
std::optional<ArucoSighting> findArucoMarker(const cv::Mat& grey, int id);

/** The crossing of the diagonals 0–2 and 1–3 of @p c (pixels). */
Eigen::Vector2d diagonalCrossing(const std::array<Eigen::Vector2d, 4>& c);

}  // namespace mrolr::stereo
