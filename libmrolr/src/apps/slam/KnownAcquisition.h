#pragma once
// Known features (thesis 5.6.2) acquired the way the thesis did: from the start pose, fixate the
// landmark, choose a well-textured patch there, lock on and store it with its triangulated position.
#include <mrolr/vision/KnownFeatures.h>
#include <mrolr/world/World.h>
#include "LiveHeads.h"
#include "SlamSetup.h"

#include <string>
#include <vector>

namespace mrolr::apps
{
/** The landmarks @p names (default: those flagged known in the world), fixated from the start pose
 * @p x0 (W) with the head of @p device. For a planar landmark ([patch.NAME]) drawn on its surface
 * (LiveHead::rendersSurfaces) the patch is the best
 * Shi–Tomasi corner (eq 5.20) within a box of [vision] known_search_box_px around the fixated
 * centre (the centre of a sign can be a flat or edge-only patch that slides along the edge). The
 * world's position only aims the head; the stored position is the stereo triangulation of the
 * locked-on patch (eq 5.13), never the world's. Throws for a name that is not a landmark of the
 * world and when lock-on fails. */
std::vector<vision::KnownFeature> acquireKnown(const world::World& w, LiveHead& device,
                                               const geometry::BiSightHead& head,
                                               const SlamSetup& s, const Eigen::Vector3d& x0,
                                               const std::vector<std::string>& names = {});

}  // namespace mrolr::apps
