#pragma once
/** Disparities for the edgels that the edge matcher (EdgeMatcher.h) left unmatched, taken from a
 * dense disparity map of the rectified pair (OpenCV's StereoSGBM, as the mission's obstacle
 * stereo uses). Edges along the scanlines cannot be matched edgel by edgel, and short strokes on a
 * textured face often find no unique partner, but the block matcher sees the surfaces next to
 * them. An edgel takes the disparity of the NEARER of its two sides (sampled 2..side_offset_px px
 * along the gradient each way): at an occluding edge the edge belongs to the foreground, and on a mark
 * or crease both sides agree. Runs of such edgels (split at disparity jumps) are 3D edge strings
 * that go to the same line and conic fitting (Fit3's segmentString). */

#include <mrolr/stereo/EdgeMatcher.h>
#include <mrolr/stereo/EdgeStrings.h>
#include <mrolr/stereo/Fit3.h>
#include <mrolr/stereo/Rectifier.h>

#include <mrpt/config/CConfigFileBase.h>

#include <opencv2/core.hpp>

#include <iosfwd>
#include <string>
#include <vector>

namespace mrolr::stereo
{
/** Options of dense edge stereo (keys dense_* of [scene]). */
struct DenseEdgeOptions
{
	bool enabled = false;          ///< dense_edge_stereo
	int block_size_px = 5;         ///< SGBM block (odd)
	double min_depth_mm = 500;     ///< dense search range (sets the largest disparity)
	double max_depth_mm = 2500;    ///< (sets the smallest disparity)
	double side_offset_px = 4;     ///< an edgel's sides are sampled 2..this px away
	double max_side_spread_px = 1; ///< samples of one side must agree within this (px)
	double max_disparity_jump_px = 1.0;  ///< between consecutive edgels of a dense 3D string
	int min_run_edgels = 10;       ///< shorter runs of densely placed edgels are dropped
	bool unmatched_only = true;    ///< false: the matched edgels join the runs with their own d
	/** true: both sides must be known; false: one known side is enough (SGBM leaves textureless
	 * surfaces such as the dark table unknown, so an object's contour often has only its own
	 * side) */
	bool require_both_sides = false;

	void loadFromConfigFile(const mrpt::config::CConfigFileBase& cfg, const std::string& section);
	void dump(std::ostream& out) const;
};

/** Dense disparity (CV_32F, px, NaN where unknown) of a rectified pair (CV_8U) for disparities in
 * [d_min_px, d_max_px] (negative ones too): StereoSGBM with the borders padded so that every
 * column is searched; matches into the right image's padding are unknown. */
cv::Mat denseDisparity(const cv::Mat& left_rect, const cv::Mat& right_rect, double d_min_px,
                       double d_max_px, const DenseEdgeOptions& o);

/** The disparity of edgel @p e from the dense map: the nearer (larger) of the disparities of its
 * two sides, each the median of the samples at 2..side_offset_px px along ±gradient when they are
 * all known and agree within max_side_spread_px; with one side unknown the other one (NaN with
 * require_both_sides); NaN when neither is known. */
double edgelDisparity(const Edgel& e, const cv::Mat& disparity, const DenseEdgeOptions& o);

/** 3D edge strings of the left strings' edgels that have no point match in @p matches (sorted by
 * string, edgel, as matchEdgeStrings returns them), placed at the dense disparity; with
 * unmatched_only = false the matched edgels join with their own disparity. Runs break at an edgel
 * without a disparity and at jumps over max_disparity_jump_px; runs shorter than min_run_edgels
 * are dropped. */
std::vector<std::vector<StereoEdgel>> denseEdgeStrings(const std::vector<EdgeString>& left,
                                                       const std::vector<EdgeMatch>& matches,
                                                       const cv::Mat& disparity,
                                                       const Rectifier& rect,
                                                       const DenseEdgeOptions& o);

}  // namespace mrolr::stereo
