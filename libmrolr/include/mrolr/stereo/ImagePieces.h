#pragma once
/** 2D segmentation of rectified edge strings into straight pieces and elliptical arcs, done on all
 * edgels of a string before any matching (thesis 4.3.2.3, Geom3's split in the image): a piece
 * straight within line_tol_px is a line, one elliptical within conic_tol_px over min_arc_deg is
 * an arc, anything else splits at the edgel farthest from its chord. A line piece also carries the
 * mean grey level on each side of it, which lets whole segments be matched between the images. */

#include <mrolr/stereo/EdgeStrings.h>
#include <mrolr/stereo/Fit3.h>

#include <opencv2/core.hpp>

#include <optional>
#include <vector>

namespace mrolr::stereo
{
/** One piece [lo, hi) of edge string @p string (rectified px). */
struct ImagePiece
{
	int string = 0;
	size_t lo = 0, hi = 0;
	bool is_line = true;
	cv::Point2d a, b;         ///< line: ends of the fitted 2D line, a above b (or left of b)
	cv::RotatedRect ellipse;  ///< arc: the fitted 2D ellipse
	double side_left = 0, side_right = 0;  ///< line: mean grey 2.5 px either side (of a → b)
};

/** Pieces of every string; @p grey is the rectified image the strings came from (8-bit). */
std::vector<ImagePiece> segmentImageStrings(const std::vector<EdgeString>& strings,
                                            const cv::Mat& grey, const FitOptions& o);

/** Intersection (px) of the image lines through a → b and c → d; nothing when they cross at less
 * than 20° (a corner is not located along nearly parallel lines). */
std::optional<cv::Point2d> lineIntersection(cv::Point2d a, cv::Point2d b, cv::Point2d c,
                                            cv::Point2d d);

/** The image points of a piece's edgels, in order. */
std::vector<cv::Point2d> piecePoints(const std::vector<EdgeString>& strings, const ImagePiece& p);

}  // namespace mrolr::stereo
