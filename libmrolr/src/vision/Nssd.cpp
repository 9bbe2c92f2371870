#include <mrolr/vision/Nssd.h>
#include <mrolr/vision/VisionError.h>

#include <opencv2/imgproc.hpp>

#include <cmath>
#include <string>

namespace mrolr::vision
{
namespace
{
void requireGray(const cv::Mat& m, const char* what)
{
	if (m.empty() || m.channels() != 1 || (m.depth() != CV_8U && m.depth() != CV_32F))
		throw VisionError(std::string(what) +
		                  ": expected a non-empty single-channel CV_8U or CV_32F image");
}

/** (g − ḡ)/σ as CV_64F; σ is the population standard deviation. Returns false when σ = 0. */
bool normalised(const cv::Mat& g, cv::Mat& out)
{
	cv::Scalar mean, stddev;
	cv::meanStdDev(g, mean, stddev);
	if (stddev[0] <= 1e-12) return false;
	g.convertTo(out, CV_64F, 1.0 / stddev[0], -mean[0] / stddev[0]);
	return true;
}

/** Eq 5.21 for one window against the already normalised saved patch. */
double nssdWindow(const cv::Mat& window, const cv::Mat& saved_normalised)
{
	cv::Mat w;
	if (!normalised(window, w)) return 2.0;
	return cv::norm(w, saved_normalised, cv::NORM_L2SQR) / static_cast<double>(w.total());
}

cv::Mat nssdMapDirect(const cv::Mat& image, const cv::Mat& saved_normalised)
{
	const int rows = image.rows - saved_normalised.rows + 1;
	const int cols = image.cols - saved_normalised.cols + 1;
	cv::Mat map(rows, cols, CV_32F);
	for (int y = 0; y < rows; ++y)
		for (int x = 0; x < cols; ++x)
		{
			const cv::Rect r(x, y, saved_normalised.cols, saved_normalised.rows);
			map.at<float>(y, x) = static_cast<float>(nssdWindow(image(r), saved_normalised));
		}
	return map;
}
}  // namespace

double nssd(const cv::Mat& saved_patch, const cv::Mat& image_patch)
{
	requireGray(saved_patch, "nssd: saved patch");
	requireGray(image_patch, "nssd: image patch");
	if (saved_patch.size() != image_patch.size())
		throw VisionError("nssd: the saved patch and the image patch differ in size");
	cv::Mat g0;
	if (!normalised(saved_patch, g0))
		throw VisionError("nssd: the saved patch is flat (zero variance); eq 5.21 is undefined");
	return nssdWindow(image_patch, g0);
}

cv::Mat nssdMap(const cv::Mat& image, const cv::Mat& patch, NssdMethod method)
{
	requireGray(image, "nssdMap: image");
	requireGray(patch, "nssdMap: patch");
	if (image.depth() != patch.depth())
		throw VisionError("nssdMap: the image and the patch have different pixel depths");
	if (patch.rows > image.rows || patch.cols > image.cols)
		throw VisionError("nssdMap: the patch is larger than the searched image region");
	cv::Mat g0;
	if (!normalised(patch, g0))
		throw VisionError("nssdMap: the saved patch is flat (zero variance); eq 5.21 is undefined");
	if (method == NssdMethod::Direct) return nssdMapDirect(image, g0);
	cv::Mat rho;
	cv::matchTemplate(image, patch, rho, cv::TM_CCOEFF_NORMED);
	return 2.0 * (1.0 - rho);
}

}  // namespace mrolr::vision
