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

}  // namespace mrolr::recog
