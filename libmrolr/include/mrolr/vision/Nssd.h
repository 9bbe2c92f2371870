#pragma once
/** Normalised sum of squared differences between a saved feature patch and image patches (thesis
 * eq 5.21, Davison [Dav98]):
 *   N = (1/n) Σ_patch [ (g1 − ḡ1)/σ1 − (g0 − ḡ0)/σ0 ]²
 * with g0 the saved patch, g1 the image patch, ḡ and σ their means and (population) standard
 * deviations and n the number of pixels. N = 0 for a perfect match, N ≤ 4, and N is unchanged by
 * any brightness gain and offset of either patch. Expanding the square gives N = 2 (1 − ρ) with ρ
 * the correlation coefficient, which is what OpenCV's matchTemplate(TM_CCOEFF_NORMED) computes:
 * both routes below give the same map (to float rounding) and bench/vision times them. */

#include <opencv2/core.hpp>

namespace mrolr::vision
{
/** Which implementation computes an NSSD map. */
enum class NssdMethod
{
	OpenCv,  ///< cv::matchTemplate(TM_CCOEFF_NORMED), N = 2 (1 − ρ)
	Direct   ///< eq 5.21 literally, window by window
};

/** N of eq 5.21 between two single-channel patches of equal size (CV_8U or CV_32F). Throws
 * VisionError for different sizes or types, and for a flat patch (σ = 0, N undefined). */
double nssd(const cv::Mat& saved_patch, const cv::Mat& image_patch);

/** N for every placement of @p patch inside @p image (both single-channel, same depth, CV_8U or
 * CV_32F): a CV_32F map of size (W − w + 1) × (H − h + 1) whose entry (y, x) belongs to the patch
 * with its top-left corner at (x, y). Windows without any intensity variation score 2 (ρ = 0), like
 * OpenCV. Throws VisionError for a flat patch, a patch larger than the image or wrong types. */
cv::Mat nssdMap(const cv::Mat& image, const cv::Mat& patch, NssdMethod method = NssdMethod::OpenCv);

}  // namespace mrolr::vision
