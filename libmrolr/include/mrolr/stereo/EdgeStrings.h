#pragma once
/** Sub-pixel edge strings (thesis 4.3.2.3 "Canny edge detection ... linked into strings ... to
 * sub-pixel accuracy"): OpenCV's EdgeDrawing (ximgproc) finds one-pixel-wide edge chains already
 * linked in order; each edgel is then moved to the sub-pixel maximum of the gradient magnitude
 * along the gradient direction (parabola through three samples). */

#include <mrpt/config/CConfigFileBase.h>

#include <opencv2/core.hpp>

#include <iosfwd>
#include <string>
#include <vector>

namespace mrolr::stereo
{
/** An edge element: sub-pixel position (px) and the image gradient there (grey levels per px). */
struct Edgel
{
	cv::Point2d p;
	cv::Point2d grad;
	/** Unit tangent along the edge (gradient rotated by +90°). */
	cv::Point2d tangent() const;
};

/** An ordered string of edgels along one edge chain. */
using EdgeString = std::vector<Edgel>;

/** Edge detection options ([section] keys as named). */
struct EdgeOptions
{
	double blur_sigma_px = 1.0;   ///< Gaussian smoothing before gradients
	int gradient_threshold = 24;  ///< EdgeDrawing gradient threshold (Sobel units / 4)
	int anchor_threshold = 8;     ///< EdgeDrawing anchor threshold
	int min_string_edgels = 12;   ///< shorter strings are dropped

	void loadFromConfigFile(const mrpt::config::CConfigFileBase& cfg, const std::string& section);
	void dump(std::ostream& out) const;
};

/** Edge strings of a grey (8-bit) image. Throws std::invalid_argument for an empty or non-8-bit
 * image. */
std::vector<EdgeString> detectEdgeStrings(const cv::Mat& grey, const EdgeOptions& options);

}  // namespace mrolr::stereo
