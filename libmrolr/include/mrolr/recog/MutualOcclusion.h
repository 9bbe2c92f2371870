#pragma once
/** Mutual occlusion between recognised objects (beyond the thesis; docs/recog.md): an object
 * partly hidden behind another cannot show min_score of its edges in the images, however well it
 * fits what is visible. Once the objects in front are recognised, the regions they cover
 * (ImageVerifier::withOccluders) are left out of the image score of the others, which are then
 * searched again. */

#include <mrolr/recog/ImageVerifier.h>
#include <mrolr/recog/Recognizer.h>

#include <vector>

namespace mrolr::recog
{
/** The found results among @p results (same order as @p recs; poses in the left camera frame L)
 * as occluders, all but the one at index @p skip; edge samples every @p spacing_mm. */
std::vector<Occluder> occludersOf(const std::vector<const Recognizer*>& recs,
                                  const std::vector<RecognitionResult>& results, size_t skip,
                                  double spacing_mm);

/** Centroid of edge samples (model frame, mm). */
Eigen::Vector3d centroidOf(const std::vector<EdgeSample>& samples_O);

/** True when @p rec's model at @p T_OinL and one of @p occluders occupy the same space: either's
 * sample centroid inside the other's solid (SelfOcclusion::contains). A model found behind others
 * must stand beside them, not in them: fitted into a found can's outline, an absent box's front
 * matches the can's edges while its back is "hidden" by the can. */
bool interpenetrates(const Recognizer& rec, const Eigen::Isometry3d& T_OinL,
                     const std::vector<Occluder>& occluders);

}  // namespace mrolr::recog
