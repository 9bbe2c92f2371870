#pragma once
/** Edges along the scanlines. Scanline stereo cannot match an edge that runs along the epipolar
 * lines (every point of it matches every other), so such edges are missing from the matched
 * strings. Their ends are usually corners where matchable edges meet: a near-horizontal straight
 * piece of a left edge string takes the disparity of the matched edgels of the same string around
 * each of its ends (median within corner_radius_px) and is kept when the right image has an edge along the
 * predicted right segment (at least min_right_support of it within 1.5 px). */

#include <mrolr/stereo/EdgeMatcher.h>
#include <mrolr/stereo/Fit3.h>
#include <mrolr/stereo/Rectifier.h>

#include <vector>

namespace mrolr::stereo
{
struct HorizontalOptions
{
	bool enabled = true;
	double max_angle_deg = 20;    ///< pieces closer than this to the scanline direction
	double corner_radius_px = 5;  ///< matched edgels this near an end give its disparity
	double min_right_support = 0.6;
};

/** 3D lines for the near-horizontal straight pieces of the left strings that the matcher left
 * mostly unmatched. @p right_size is the rectified image size. */
std::vector<LineFit3> recoverHorizontalLines(const std::vector<EdgeString>& left,
                                             const std::vector<EdgeString>& right,
                                             const std::vector<EdgeMatch>& matches,
                                             const Rectifier& rect, cv::Size right_size,
                                             const FitOptions& fit,
                                             const HorizontalOptions& options);

}  // namespace mrolr::stereo
