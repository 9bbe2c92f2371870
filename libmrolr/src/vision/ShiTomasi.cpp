#include <mrolr/vision/ShiTomasi.h>
#include <mrolr/vision/VisionError.h>

#include <opencv2/imgproc.hpp>

#include <cmath>
#include <string>

namespace mrolr::vision
{
namespace
{
void requireInput(const cv::Mat& gray, int patch_px)
{
	if (gray.empty() || gray.type() != CV_8UC1)
		throw VisionError("Shi-Tomasi: expected a non-empty 8-bit single-channel image");
	if (patch_px < 3 || patch_px % 2 == 0)
		throw VisionError("Shi-Tomasi: patch size " + std::to_string(patch_px) +
		                  " must be odd, >= 3");
}

/** Rectangle of centres whose patch lies inside the image, intersected with @p box. */
cv::Rect validCentres(const cv::Mat& gray, const cv::Rect& box, int patch_px)
{
	const int r = patch_px / 2;
	return box & cv::Rect(r, r, gray.cols - 2 * r, gray.rows - 2 * r);
}
}  // namespace

cv::Mat minEigenvalueMap(const cv::Mat& gray, int patch_px)
{
	requireInput(gray, patch_px);
	cv::Mat lambda;
	cv::cornerMinEigenVal(gray, lambda, patch_px, 3, cv::BORDER_REFLECT101);
	return lambda;
}

std::optional<Corner> bestCornerInBox(const cv::Mat& gray, const cv::Rect& box, int patch_px,
                                      double min_eigenvalue)
{
	requireInput(gray, patch_px);
	const cv::Rect centres = validCentres(gray, box, patch_px);
	if (centres.empty()) return std::nullopt;
	// The window plus one pixel for the Sobel kernel, so border handling never reaches the result.
	const int margin = patch_px / 2 + 1;
	const cv::Rect roi = cv::Rect(centres.x - margin, centres.y - margin,
	                              centres.width + 2 * margin, centres.height + 2 * margin) &
	                     cv::Rect(0, 0, gray.cols, gray.rows);
	const cv::Mat lambda = minEigenvalueMap(gray(roi), patch_px);
	double best = 0;
	cv::Point at;
	const cv::Rect inRoi(centres.x - roi.x, centres.y - roi.y, centres.width, centres.height);
	cv::minMaxLoc(lambda(inRoi), nullptr, &best, nullptr, &at);
	if (best < min_eigenvalue || best <= 0) return std::nullopt;
	return Corner{{double(centres.x + at.x), double(centres.y + at.y)}, best};
}

cv::Mat extractPatch(const cv::Mat& gray, const Eigen::Vector2d& uv, int patch_px)
{
	const int r = patch_px / 2;
	const int cu = static_cast<int>(std::lround(uv.x())),
	          cv_ = static_cast<int>(std::lround(uv.y()));
	const cv::Rect rect(cu - r, cv_ - r, patch_px, patch_px);
	if (gray.empty() || (rect & cv::Rect(0, 0, gray.cols, gray.rows)) != rect)
		throw VisionError("extractPatch: a " + std::to_string(patch_px) + " px patch at (" +
		                  std::to_string(cu) + ", " + std::to_string(cv_) +
		                  ") does not lie inside the " + std::to_string(gray.cols) + "x" +
		                  std::to_string(gray.rows) + " image");
	return gray(rect).clone();
}

}  // namespace mrolr::vision
