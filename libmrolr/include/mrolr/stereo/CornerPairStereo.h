#pragma once
/** Stereo of straight edges along the scanlines from their two corners (thesis 4.3.2.3; the
 * segment-based matching of SegmentStereo.h). Such an edge has no usable disparity along its
 * length: both interpretation planes contain the baseline. Its ends, though, are usually corners
 * where the edge string turns into another edge, and a corner is a point feature that both images
 * show on the same rectified row. Each end of a near-horizontal line piece is refined to the
 * intersection with the neighbouring line piece of its string (sub-pixel, whatever the split
 * point); a left piece is paired with the right piece along the scanlines whose two corners lie
 * on the same rows (within corner_row_tol_px), with similar direction, a matching grey level on
 * one side and disparities in range, and the 3D line joins the two triangulated corners. Pieces
 * whose ends are not corners in both images (an image border, an occluded end) are not paired. */

#include <mrolr/stereo/SegmentStereo.h>

#include <optional>

namespace mrolr::stereo
{
/** The 3D line (mm, thesis L) of left line piece @p left_index of @p in from its corner pair, or
 * nothing when no right piece pairs up unambiguously. */
std::optional<LineFit3> cornerPairLine(const PieceStereoInput& in, size_t left_index,
                                       const Rectifier& rect, const SegmentStereoOptions& o);

}  // namespace mrolr::stereo
