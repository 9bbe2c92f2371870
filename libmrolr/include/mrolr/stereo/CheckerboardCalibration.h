#pragma once
/** Stereo calibration from checkerboard image pairs with OpenCV (thesis 4.3.2.1, done here the
 * modern way): findChessboardCorners + cornerSubPix in every image, calibrateCamera per camera,
 * then stereoCalibrate with the intrinsics as the initial guess. */

#include <mrolr/stereo/StereoCalibration.h>

#include <opencv2/core.hpp>

#include <string>
#include <vector>

namespace mrolr::stereo
{
/** The calibration board: inner corners per row and column and the square side. */
struct BoardSpec
{
	int cols = 9;  ///< inner corners along a row
	int rows = 6;  ///< inner corners along a column
	double square_mm = 34.0;
};

/** Parses "COLSxROWS" (e.g. "9x6"); throws std::invalid_argument naming the text. */
BoardSpec parseBoardSize(const std::string& text, double square_mm);

/** Sub-pixel inner corners of the board in a grey image (px); empty when the board is not found. */
std::vector<cv::Point2f> findBoardCorners(const cv::Mat& grey, const BoardSpec& board);

/** Board corner coordinates in the board plane (mm, z = 0), row-major as OpenCV orders them. */
std::vector<cv::Point3f> boardObjectPoints(const BoardSpec& board);

/** Calibrates from paired image files (same count, paired by position). Pairs in which either
 * image lacks the full board are skipped; throws std::runtime_error when an image cannot be read,
 * sizes differ, or fewer than 2 pairs remain. */
StereoCalibration calibrateStereo(const std::vector<std::string>& left_files,
                                  const std::vector<std::string>& right_files,
                                  const BoardSpec& board);

/** As above from images already in memory (grey or colour). */
StereoCalibration calibrateStereo(const std::vector<cv::Mat>& left,
                                  const std::vector<cv::Mat>& right, const BoardSpec& board);

}  // namespace mrolr::stereo
