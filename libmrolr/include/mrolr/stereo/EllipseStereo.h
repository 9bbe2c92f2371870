#pragma once
/** Stereo of conics from their two image ellipses (thesis 4.3.2.3; the "ellipses fitted in
 * 2D in both images ... sampled points triangulated along the ellipse using the other image's
 * ellipse"). In rectified images a left arc is paired with the right arc whose extreme rows agree
 * (within 2 px), of similar size (semi-axes within 25 %) and at a disparity in range. On every row
 * the left and right crossings of the two ellipses correspond, and the topmost and bottommost
 * points (the epipolar tangencies) correspond exactly, so a rim gets disparities where it runs
 * along the scanlines and edgel matching fails. */

#include <mrolr/stereo/Fit3.h>
#include <mrolr/stereo/ImagePieces.h>
#include <mrolr/stereo/SegmentStereo.h>

#include <vector>

namespace mrolr::stereo
{
/** Stereo samples (rectified left pixel, disparity, 3D point in L) of the conic of left arc @p p,
 * on 40 rows and at the two tangencies, keeping only points that lie on both arcs (1.5 px). Empty
 * without a consistent right arc. */
std::vector<StereoEdgel> ellipsePairSamples(const PieceStereoInput& in, const ImagePiece& p,
                                            const Rectifier& rect);

}  // namespace mrolr::stereo
