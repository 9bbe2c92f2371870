#pragma once
/** Feature acquisition by the Shi–Tomasi operator (thesis 5.2, eq 5.20): for the patch around each
 * pixel, Z = Σ_patch [gx² gx·gy; gx·gy gy²] with gx, gy the image gradients; the best feature is
 * the patch whose smaller eigenvalue λ_min of Z is largest. OpenCV's cornerMinEigenVal computes
 * λ_min of the window-averaged Z (Sobel 3×3 gradients scaled to [0, 1] intensities). */

#include <Eigen/Core>
#include <opencv2/core.hpp>

#include <optional>

namespace mrolr::vision
{
/** A detected feature: the centre pixel of its patch and λ_min of eq 5.20. */
struct Corner
{
	Eigen::Vector2d uv = Eigen::Vector2d::Zero();  ///< patch centre, pixels (column, row)
	double min_eigenvalue = 0;                     ///< λ_min of Z (OpenCV's normalised scale)
};

/** λ_min of eq 5.20 at every pixel of @p gray (CV_8U), with a @p patch_px × @p patch_px window. */
cv::Mat minEigenvalueMap(const cv::Mat& gray, int patch_px);

/** The best feature whose whole patch lies in the image and whose centre lies in @p box (pixels of
 * @p gray): the largest λ_min, if it is at least @p min_eigenvalue. Only the box plus a margin is
 * processed. Throws VisionError for a non-8-bit or multi-channel image or an even patch size. */
std::optional<Corner> bestCornerInBox(const cv::Mat& gray, const cv::Rect& box, int patch_px,
                                      double min_eigenvalue);

/** The @p patch_px × @p patch_px patch centred on the integer pixel nearest @p uv (a deep copy).
 * Throws VisionError if the patch does not lie wholly inside the image. */
cv::Mat extractPatch(const cv::Mat& gray, const Eigen::Vector2d& uv, int patch_px);

}  // namespace mrolr::vision
