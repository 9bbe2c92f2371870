#pragma once
/** 3D wire-frame of a scene from one stereo pair (thesis 4.3.2.3): rectification, sub-pixel edge
 * strings, PMF-style scanline matching, 3D edge strings, and their segmentation into 3D lines and
 * conics. Output in millimetres in the thesis left camera frame L (x left, y up, z forward). */

#include <mrolr/stereo/EdgeMatcher.h>
#include <mrolr/stereo/EdgeStrings.h>
#include <mrolr/stereo/Fit3.h>
#include <mrolr/stereo/EdgeOnRims.h>
#include <mrolr/stereo/HorizontalCircles.h>
#include <mrolr/stereo/HorizontalEdges.h>
#include <mrolr/stereo/Rectifier.h>
#include <mrolr/stereo/SegmentStereo.h>
#include <mrolr/stereo/StereoCalibration.h>

#include <mrpt/config/CConfigFileBase.h>

#include <iosfwd>
#include <string>
#include <optional>
#include <vector>

namespace mrolr::stereo
{
/** All options of scene reconstruction, read from one .ini section (config/model.ini [scene]). */
struct SceneOptions
{
	double min_depth_mm = 300;   ///< nearest depth searched (sets the largest disparity)
	double max_depth_mm = 3000;  ///< farthest depth searched (sets the smallest disparity)
	RectifyOptions rectify;      ///< how much of the source images the rectified ones keep
	int border_margin_px = 2;    ///< edgels this near the edge of the source image are dropped
	EdgeOptions edges;
	MatchOptions match;
	FitOptions fit;
	HorizontalOptions horizontal;
	SegmentStereoOptions segments;  ///< piece stereo (SegmentStereo.h) adds what 3D strings miss
	HorizontalCircleOptions circles;  ///< rims as horizontal circles (needs the up direction)
	EdgeOnRimOptions edge_on_rims;    ///< rims seen edge-on (needs the up direction)

	/** The shipped reconstruction: the steps' own defaults, with the values docs/model.md measured
	 * for the scene (each reason beside it in SceneReconstruction.cpp). [scene] of a file sets the
	 * depth range; every other key is optional and overrides one of these. */
	SceneOptions();
	void loadFromConfigFile(const mrpt::config::CConfigFileBase& cfg, const std::string& section);
	void dump(std::ostream& out) const;
};

/** The reconstructed segments and counts of the intermediate stages. */
struct StereoScene
{
	std::vector<LineFit3> lines;
	std::vector<ConicFit3> conics;
	size_t left_strings = 0, right_strings = 0, matches = 0, strings3d = 0;
	size_t horizontal_lines = 0;  ///< lines recovered from their corners (HorizontalEdges.h)
	size_t piece_features = 0;    ///< lines and conics added by piece stereo (SegmentStereo.h)
	size_t circle_features = 0;   ///< horizontal circles added (HorizontalCircles.h)
	size_t edge_on_rims = 0;      ///< rims seen edge-on added (EdgeOnRims.h)
};

/** Splits the matched edgels of each left string into 3D edge strings: a new string starts after
 * more than max_gap_edgels unmatched edgels or a disparity jump beyond max_disparity_jump_px. */
std::vector<std::vector<StereoEdgel>> stereoStrings(const std::vector<EdgeMatch>& matches,
                                                    const Rectifier& rect, const FitOptions& o);

/** Piece stereo (SegmentStereo.h) of the rectified pair's strings: adds to @p scene the features
 * the 3D strings missed. */
void addPieceFeatures(const std::vector<EdgeString>& left, const std::vector<EdgeString>& right,
                      const cv::Mat& left_rect, const cv::Mat& right_rect,
                      const std::vector<EdgeMatch>& matches, const Rectifier& rect,
                      const SceneOptions& o, StereoScene& scene);

/** Horizontal circles (HorizontalCircles.h) of the left arcs that no conic of @p scene covers;
 * adds them to @p scene. @p up_L: the up direction in L. */
void addHorizontalCircles(const std::vector<EdgeString>& left, const std::vector<EdgeString>& right,
                          const cv::Mat& left_rect,
                          const std::vector<EdgeMatch>& matches, const Rectifier& rect,
                          const Eigen::Vector3d& up_L, const SceneOptions& o, StereoScene& scene);

/** Reconstructs a scene from an unrectified stereo pair (grey or colour, the calibration's size).
 * @p up_L: the up direction in the left camera frame L when the head angles are known; the
 * horizontal-circle step (options.circles) runs only with it. Throws std::runtime_error for
 * images that do not fit the calibration. */
StereoScene reconstructScene(const cv::Mat& left, const cv::Mat& right,
                             const StereoCalibration& calib, const SceneOptions& options,
                             const std::optional<Eigen::Vector3d>& up_L = std::nullopt);

}  // namespace mrolr::stereo
