#pragma once
/** Mutual occlusion between recognised objects (beyond the thesis; docs/recog.md): an object
 * partly hidden behind another cannot show min_score of its edges in the images, however well it
 * fits what is visible. Once the objects in front are recognised, the regions they cover
 * (ImageVerifier::withOccluders) are left out of the image score of the others, which are then
 * searched again. */

#include <mrolr/recog/images/ImageVerifier.h>
#include <mrolr/recog/Recognizer.h>

#include <functional>
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

/** One model searched again behind the found ones: recognise model @p i with @p behind (the
 * pair's evidence with the occluders' regions left out of the image score). */
using SearchBehind = std::function<RecognitionResult(size_t i, const ImageVerifier& behind)>;

/** The second search of mutual occlusion, the one used by mrolr-recognize, the rendered
 * evaluation and the mission: every model of @p recs not found in @p first (same order) is
 * searched again by @p search with the others found in @p first as occluders
 * (ImageVerifier::withOccluders of @p images). A find that interpenetrates none of them
 * replaces its result, its `occluders` the number it was found behind; either way the second
 * search's time is added to the model's `ms` and `times`. @p search should say
 * SceneContext::repeat: the scene is the one each Recognizer searched first. Edge samples every
 * @p spacing_mm. Returns the results after the second search, same order as @p recs. */
std::vector<RecognitionResult> searchBehindFound(const std::vector<const Recognizer*>& recs,
                                                 const std::vector<RecognitionResult>& first,
                                                 const ImageVerifier& images, double spacing_mm,
                                                 const SearchBehind& search);

}  // namespace mrolr::recog
