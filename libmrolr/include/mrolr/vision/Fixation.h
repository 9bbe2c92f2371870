#pragma once
/** Feature acquisition and fixation (thesis 5.3): find the best Shi–Tomasi patch in a box of the
 * left image, match it along the epipolar band of the right image, triangulate, drive the head to
 * fixate the point, and lock on when the patch centre is within a small radius (2 px) of the
 * principal point in both images; otherwise re-triangulate from the new images and repeat, and
 * discard the feature after a configurable number of attempts. */

#include <mrolr/vision/PatchSearch.h>
#include <mrolr/vision/ShiTomasi.h>
#include <mrolr/vision/StereoHeadDevice.h>
#include <mrolr/vision/VisionOptions.h>

#include <Eigen/Core>
#include <opencv2/core.hpp>

#include <string>

namespace mrolr::vision
{
/** What a fixation did. When locked, angles/pixels/p_GinC0 describe the final, fixated view. */
struct FixationResult
{
	bool locked = false;
	int attempts = 0;               ///< head movements made
	geometry::HeadAngles angles;    ///< radians, last head position
	geometry::StereoPixels pixels;  ///< matched patch centres at those angles, pixels
	Eigen::Vector3d p_GinC0 = Eigen::Vector3d::Zero();  ///< triangulated point, C0, metres
	Eigen::Matrix3d cov_C0 = Eigen::Matrix3d::Zero();   ///< its covariance, m²
	double score_left = 0, score_right = 0;             ///< NSSD of the last matches (eq 5.21)
	std::string failure;  ///< why the feature was discarded; empty when locked
};

/** Fixates the feature whose saved patch is @p patch, starting from the guess @p p_guess_inC0
 * (C0, metres). Never throws for a feature that cannot be fixated (joint limits, lost patch):
 * the result says why. */
FixationResult fixateOnPatch(StereoHeadDevice& device, const geometry::BiSightHead& head,
                             const cv::Mat& patch, const Eigen::Vector3d& p_guess_inC0,
                             const VisionOptions& options);

/** True when both image positions lie within @p radius_px of the principal point. */
bool isLockedOn(const geometry::StereoPixels& px, const geometry::PinholeCamera& camera,
                double radius_px);

/** A newly acquired feature: its saved patch (from the left image) and how fixation went. */
struct Acquisition
{
	bool ok = false;
	Corner corner;           ///< the Shi–Tomasi feature in the first left image
	cv::Mat patch;           ///< the saved patch, CV_8UC1, patch_size_px square
	PatchMatch right_match;  ///< its epipolar match in the first right image
	FixationResult fixation;
	std::string failure;  ///< why nothing was acquired; empty when ok
};

/** Acquires a new feature in @p box of the left image at the head's current angles (5.3). */
Acquisition acquireFeature(StereoHeadDevice& device, const geometry::BiSightHead& head,
                           const cv::Rect& box, const VisionOptions& options);

}  // namespace mrolr::vision
