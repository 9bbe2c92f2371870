#pragma once
/** Rims seen nearly edge-on as horizontal circles (docs/model.md step 9). Objects stand
 * upright on the table, so most rims are horizontal circles; with the head angles known, the up
 * direction in the left camera frame L is known too. A horizontal circle is then fixed by one
 * image arc and one depth: the arc's edgels are back-projected onto the horizontal plane at the
 * height that the arc's stereo matches give (their median, preferring the edgels across the
 * scanlines, where matching is reliable), and a circle is fitted there, weighting each edgel's
 * radial residual by its image effect (px per mm), so that the accurate image columns, not the
 * grazing depths, fix it. The circle is kept only if its projection passes within
 * max_residual_px (RMS) of the arc's edgels and, for an arc with a 2D ellipse, the section of
 * that ellipse's viewing cone by the plane is round (a/b within max_axis_ratio): an ellipse of a
 * tilted circle is rejected. */

#include <mrolr/stereo/EdgeMatcher.h>
#include <mrolr/stereo/Fit3.h>
#include <mrolr/stereo/ImagePieces.h>
#include <mrolr/stereo/Rectifier.h>

#include <mrpt/config/CConfigFileBase.h>

#include <Eigen/Core>
#include <opencv2/core.hpp>

#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

namespace mrolr::stereo
{
/** Options of the horizontal-circle step ([scene] horizontal_circle* keys). */
struct HorizontalCircleOptions
{
	bool enabled = false;          ///< [scene] horizontal_circles (needs the up direction)
	double max_residual_px = 1.0;  ///< RMS image distance of the arc's edgels from the circle
	double max_axis_ratio = 1.3;   ///< a/b of the image ellipse's cone cut by the plane
	int min_depth_matches = 3;     ///< stereo matches on the arc that give its height
	double min_radius_mm = 5, max_radius_mm = 150;
	double min_arc_deg = 60;         ///< arc of the circle an arc piece's edgels span
	double min_run_arc_deg = 120;    ///< the same for a run of line pieces (chords)
	double max_chord_turn_deg = 45;  ///< consecutive chords of a run turn by less
	/** rescale the circle about the camera so that the disparities of its leftmost and rightmost
	 * image points match those of the right image's edgels there (rightExtremeScale) */
	bool right_extremes = true;

	void loadFromConfigFile(const mrpt::config::CConfigFileBase& cfg, const std::string& section);
	void dump(std::ostream& out) const;
};

/** The horizontal circle (normal ±@p up_L, mm in L) through the image arc @p arc_px (rectified
 * left px, in order) at height h = up_L · p of the points @p depth (median), or nothing when the
 * checks of @p o fail. @p ellipse: the arc's 2D ellipse for the axis-ratio check (none: skipped).
 */
std::optional<ConicFit3> horizontalCircle(const std::vector<cv::Point2d>& arc_px,
                                          const std::vector<StereoEdgel>& depth,
                                          const std::optional<cv::RotatedRect>& ellipse,
                                          const Eigen::Vector3d& up_L, const Rectifier& rect,
                                          const HorizontalCircleOptions& o);

/** The axis ratio a/b (>= 1) of the cut of image ellipse @p el's viewing cone by the plane with
 * normal @p up_L (any height: the ratio does not depend on it); infinity if the plane does not
 * cut the whole cone in front of the camera. */
double planeSectionAxisRatio(const cv::RotatedRect& el, const Eigen::Vector3d& up_L,
                             const Rectifier& rect);

/** Horizontal circles of the left image's arc pieces, and of runs of line pieces of one string
 * that turn smoothly (a rim so flat that its chords are straight within line_tol_px), that no
 * conic of @p existing covers in the image (half their edgels within 1.5 px of its projection);
 * depth from the point @p matches on the arc, then, with @p right_strings and
 * o.right_extremes, from the right image's extremes (rightExtremeScale). */
std::vector<ConicFit3> horizontalCircles(const std::vector<EdgeString>& left_strings,
                                         const std::vector<ImagePiece>& left_pieces,
                                         const std::vector<EdgeMatch>& matches,
                                         const std::vector<ConicFit3>& existing,
                                         const Eigen::Vector3d& up_L, const Rectifier& rect,
                                         const HorizontalCircleOptions& o,
                                         const std::vector<EdgeString>* right_strings = nullptr);

/** The scale (about the left camera centre, within ±10 %; it leaves the left image unchanged)
 * that makes the disparities of circle @p c's leftmost and rightmost image points equal those
 * measured there: the left arc's extreme columns minus the extreme columns of the right edgels
 * (@p right, rectified) within 4 px of the predicted ones on the arc's rows. Only extremes that
 * the left arc @p arc_px reaches, 5 px or more inside both images, count; nothing without one. */
std::optional<double> rightExtremeScale(const ConicFit3& c, const std::vector<cv::Point2d>& arc_px,
                                        const std::vector<EdgeString>& right,
                                        const Rectifier& rect);

}  // namespace mrolr::stereo
