#pragma once
/** What the refinement's yaw sweep (ImageVerifier::scoreIfMore) knows of a pose before the sight
 * tests of SelfOcclusion, the costly part of count(): the samples count() considers unless the
 * object hides them (in front of the camera, inside the image, not behind an Occluder), with the
 * ones an edge supports apart. Those supported bound the pose's supported count from above; each
 * unhidden one of the others bounds its supported fraction. On the bench sweep a yaw is decided
 * with 147 costly sight tests of its 940 such samples (both images), where count() made one for
 * each sample it visited. */
#include <cstdint>
#include <vector>

namespace mrolr::recog
{
/** One image's prospects of a pose (EdgeImage::prospects), in count()'s order: the samples
 * count() considers unless the object hides them, each as its index k, sample k of the
 * SightedSamples when k < samples_O.size(), else limb k − samples_O.size(). */
struct Prospects
{
	std::vector<std::uint32_t> on_edge;   ///< supported unless hidden
	std::vector<std::uint32_t> off_edge;  ///< considered and unsupported unless hidden
};

}  // namespace mrolr::recog
