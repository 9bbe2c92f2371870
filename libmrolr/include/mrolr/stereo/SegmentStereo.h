#pragma once
/** Stereo of whole image pieces (thesis 4.3.2.3; the segment-based alternative to edgel matching
 * that the issue names): left and right line pieces (ImagePieces.h) are matched as segments, and
 * each matched pair gives a 3D line as the intersection of the two interpretation planes (camera
 * centre + image line). In rectified images that intersection is the disparity d(y) = x_L(y) −
 * x_R(y) along the rows the two segments share, so the 3D ends are where the segments' epipolar
 * extents overlap. A piece near the scanline direction has no usable d(y) (both planes contain
 * the baseline); its two ends are corners where it meets matched segments, whose disparities it
 * takes, and the right image must show a segment along the predicted position. A piece across the
 * scanlines that pairs with no right segment (a box's short receding edge, which the other camera
 * sees foreshortened to a few edgels of a longer string) is placed the same way when the right
 * image has edgels along the predicted segment (EdgelSupport.h). An elliptical arc
 * of the left image is reconstructed from the samples of its ellipse pair (EllipseStereo.h), or
 * else from the point matches inside it, and back-projected whole (Fit3's conicFromEllipse). */

#include <mrolr/stereo/EdgeMatcher.h>
#include <mrolr/stereo/Fit3.h>
#include <mrolr/stereo/ImagePieces.h>
#include <mrolr/stereo/Rectifier.h>

#include <mrpt/config/CConfigFileBase.h>

#include <iosfwd>
#include <string>
#include <vector>

namespace mrolr::stereo
{
struct SegmentStereoOptions
{
	bool enabled = true;             ///< false: the 3D edge strings only (Fit3)
	double max_angle_diff_deg = 10;  ///< image directions of matched segments
	double min_row_overlap = 0.5;    ///< shared rows / rows of the shorter segment
	double max_side_diff_grey = 20;  ///< the grey level of at least one side must agree
	double horizontal_deg = 12;      ///< closer to the scanline: ends matched as corners
	double corner_radius_px = 6;     ///< such a segment's end takes the disparity of a matched
	                                 ///< segment's end this near (a corner)
	double duplicate_mm = 4;         ///< a piece feature this near a 3D-string one is not added
	double max_disparity_gradient = 1.0;  ///< |Δd| / image length along a matched segment
	int min_conic_matches = 8;            ///< point matches inside an arc for its disparity plane
	bool corner_pairs = true;             ///< pair pieces along the scanlines by their end corners
	double corner_row_tol_px = 1.0;       ///< rows of corresponding corners (CornerPairStereo.h)
	int min_line_edgels = 0;              ///< shortest line piece (0: FitOptions::min_line_edgels)
	int both_sides_below_edgels = 0;      ///< shorter pieces must match in the grey of both sides
	/** > 0: a left piece with several candidate right segments adds to each candidate's cost
	 * |d_candidate − d_corner| / this (px) at each of its ends where another matched segment (or
	 * point matches) gives the corner's disparity; 0: off */
	double corner_consistency_px = 0;
	/** A left line piece across the scanlines with no right partner (too short in the right image,
	 * or split there differently) is placed from the disparities at its two corners when the right
	 * image has edgels along corner_line_min_support of the predicted segment */
	bool corner_lines = true;
	double corner_line_min_support = 0.7;

	void loadFromConfigFile(const mrpt::config::CConfigFileBase& cfg, const std::string& section);
	void dump(std::ostream& out) const;
};

/** The stereo inputs of piece reconstruction (rectified images' strings and pieces). */
struct PieceStereoInput
{
	const std::vector<EdgeString>& left_strings;
	const std::vector<ImagePiece>& left_pieces;
	const std::vector<ImagePiece>& right_pieces;
	const std::vector<EdgeMatch>& matches;  ///< point matches (EdgeMatcher)
	double d_min_px = 0, d_max_px = 0;
	const std::vector<EdgeString>* right_strings = nullptr;  ///< for arcs of the right image
};

/** 3D lines and conics of the left pieces: matched segment pairs, segments along the scanlines
 * between matched corners, and arcs with enough point matches. */
void reconstructPieces(const PieceStereoInput& in, const Rectifier& rect, const FitOptions& fit,
                       const SegmentStereoOptions& o, std::vector<LineFit3>& lines,
                       std::vector<ConicFit3>& conics);

}  // namespace mrolr::stereo
