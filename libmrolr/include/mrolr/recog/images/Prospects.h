#pragma once
/** What the refinement's yaw sweep (ImageVerifier::scoreIfMore) knows of a pose before the sight
 * tests of SelfOcclusion, the costly part of count(): the samples count() considers unless the
 * object hides them (in front of the camera, inside the image, not behind an Occluder), with the
 * ones an edge supports apart. Those supported bound the pose's supported count from above; each
 * unhidden one of the others bounds its supported fraction. Most yaws of a sweep are ruled out on
 * both after a few sight tests, where count() makes one per sample. */
#include <mrolr/recog/SelfOcclusion.h>
#include <mrolr/recog/images/Limbs.h>

#include <vector>

namespace mrolr::recog
{
/** A sample of a pose that count() considers unless the object hides it. */
struct Prospect
{
	const EdgeSample* sample = nullptr;
	/** Its sight (SightedSamples::sights); null for a limb, and for every sample when the
	 * samples have no SelfOcclusion (nothing is hidden then). */
	const SelfOcclusion::PointSight* sight = nullptr;
};

/** One image's Prospects of a pose (EdgeImage::prospects), in count()'s order. */
struct Prospects
{
	std::vector<Prospect> on_edge;   ///< supported unless hidden
	std::vector<Prospect> off_edge;  ///< considered and unsupported unless hidden
};

}  // namespace mrolr::recog
