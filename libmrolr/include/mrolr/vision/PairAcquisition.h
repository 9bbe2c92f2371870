#pragma once
/** A new feature from one stereo pair, without moving the head (thesis 5.2–5.3): the best
 * Shi–Tomasi patch (eq 5.20) in a box of the left image, its NSSD match (eq 5.21) along the
 * epipolar band of the right image (±7 px), and the triangulated point (4.2.3). Live acquisition
 * then fixates the point (Fixation.h); a rawlog replay, whose head cannot be steered, uses the
 * triangulation as it is. */

#include <mrolr/vision/PatchSearch.h>
#include <mrolr/vision/ShiTomasi.h>
#include <mrolr/vision/StereoHeadDevice.h>
#include <mrolr/vision/VisionOptions.h>

#include <Eigen/Core>
#include <opencv2/core.hpp>

#include <string>

namespace mrolr::vision
{
/** What acquisition in one pair found. */
struct PairAcquisition
{
	bool ok = false;                ///< a patch was found in both images and triangulated
	Corner corner;                  ///< the Shi–Tomasi feature in the left image
	cv::Mat patch;                  ///< the saved patch, CV_8UC1, patch_size_px square
	PatchMatch right_match;         ///< its epipolar match in the right image
	geometry::StereoPixels pixels;  ///< matched centres, pixels
	Eigen::Vector3d p_GinC0 = Eigen::Vector3d::Zero();  ///< triangulated point, C0, metres
	std::string failure;                                ///< why nothing was acquired
};

/** Acquires a feature in @p box (pixels of the left image) of @p images, taken at images.angles.
 * Never throws for a feature that is not found or cannot be triangulated: ok = false and failure
 * says why. */
PairAcquisition acquireInPair(const StereoImages& images, const geometry::BiSightHead& head,
                              const cv::Rect& box, const VisionOptions& options);

}  // namespace mrolr::vision
