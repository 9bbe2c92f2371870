#pragma once
/** Measuring a mapped feature from a stereo pair (thesis 5.5.4): the predicted measurement
 * h = (pan, elevation, vergence) of the ideal head (eq 5.40) and its innovation covariance S (eq
 * 5.36) give an n-σ ellipse in each image (eqs 5.37–5.39); the saved patch is sought inside each
 * ellipse by NSSD (eq 5.21), the two matches are triangulated (4.2.3) and the point is turned into
 * the measured ideal-head angles that the filter consumes. */

#include <mrolr/vision/PatchSearch.h>
#include <mrolr/vision/StereoHeadDevice.h>
#include <mrolr/vision/VisionOptions.h>

#include <Eigen/Core>

namespace mrolr::vision
{
/** Outcome of one feature measurement. */
struct FeatureMeasurement
{
	bool found = false;                           ///< matched in both ellipses and triangulated
	Eigen::Vector3d h = Eigen::Vector3d::Zero();  ///< measured (pan, elevation, vergence), rad
	Eigen::Vector3d p_GinC0 = Eigen::Vector3d::Zero();  ///< triangulated point, C0, metres
	geometry::StereoPixels pixels;                      ///< matched centres, pixels
	ImageEllipse ellipse_left, ellipse_right;           ///< search regions
	PatchMatch left, right;                             ///< best candidates in each image
	geometry::HeadAngles angles;                        ///< radians, the angles of the images used
};

/** The search ellipses (eqs 5.37–5.39) of a feature with predicted measurement @p h_pred and
 * innovation covariance @p S in both images taken at @p angles. Returns false when the prediction
 * cannot be projected (behind a camera, vergence outside (0, π/2)). */
bool predictRegions(const geometry::BiSightHead& head, const geometry::HeadAngles& angles,
                    const Eigen::Vector3d& h_pred, const Eigen::Matrix3d& S,
                    const VisionOptions& options, FeatureMeasurement& m);

/** Matches @p patch inside the ellipses already in @p m, triangulates and fills h (eq 5.40). */
void matchInRegions(const StereoImages& images, const geometry::BiSightHead& head,
                    const cv::Mat& patch, const VisionOptions& options, NssdMethod method,
                    FeatureMeasurement& m);

/** Measures the feature of saved @p patch in @p images, given the predicted ideal-head measurement
 * @p h_pred and innovation covariance @p S (rad²). Never throws for a feature that is not found
 * or cannot be projected: found = false. */
FeatureMeasurement measureInImages(const StereoImages& images, const geometry::BiSightHead& head,
                                   const cv::Mat& patch, const Eigen::Vector3d& h_pred,
                                   const Eigen::Matrix3d& S, const VisionOptions& options,
                                   NssdMethod method = NssdMethod::OpenCv);

/** Saccades the head to fixate the predicted point, grabs a pair and measures it there. A
 * prediction beyond the joint limits gives found = false. */
FeatureMeasurement measureWithHead(StereoHeadDevice& device, const geometry::BiSightHead& head,
                                   const cv::Mat& patch, const Eigen::Vector3d& h_pred,
                                   const Eigen::Matrix3d& S, const VisionOptions& options);

}  // namespace mrolr::vision
