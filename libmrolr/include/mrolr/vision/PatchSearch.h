#pragma once
/** Search an image for a saved feature patch inside a region (thesis 5.2.1): every pixel of the
 * region is the centre of a candidate patch, scored by NSSD (eq 5.21); the lowest score below the
 * threshold (0.9) is the match. The winning position is refined to sub-pixel precision by a
 * parabola through the scores of its neighbours in u and in v. */

#include <mrolr/vision/Nssd.h>
#include <mrolr/vision/SearchRegion.h>

#include <Eigen/Core>
#include <opencv2/core.hpp>

#include <functional>
#include <limits>

namespace mrolr::vision
{
/** Outcome of one patch search. */
struct PatchMatch
{
	bool found = false;                            ///< a candidate scored below the threshold
	Eigen::Vector2d uv = Eigen::Vector2d::Zero();  ///< centre of the best patch, sub-pixel
	double score = std::numeric_limits<double>::infinity();  ///< best NSSD (eq 5.21), any value
	int candidates = 0;  ///< patch centres scored (inside the region and the image)
	/** Best NSSD among the candidates more than half a patch side from the best one (in x or y):
	 * a value close to score means an ambiguous match (repeated texture); infinity if none. */
	double second_score = std::numeric_limits<double>::infinity();
};

/** Predicate on a candidate centre (u, v), pixels: true if it belongs to the search region. */
using RegionTest = std::function<bool(const Eigen::Vector2d&)>;

/** Scores every centre in @p box (pixels, clipped to centres whose patch fits the image) that
 * passes @p inside, and returns the best. Throws VisionError for a flat patch or mismatched types.
 */
PatchMatch searchPatch(const cv::Mat& image, const cv::Mat& patch, const cv::Rect& box,
                       const RegionTest& inside, double threshold,
                       NssdMethod method = NssdMethod::OpenCv);

/** Search inside the n-σ ellipse @p region (eqs 5.37–5.39). */
PatchMatch searchEllipse(const cv::Mat& image, const cv::Mat& patch, const ImageEllipse& region,
                         double threshold, NssdMethod method = NssdMethod::OpenCv);

/** Search within the epipolar band @p band (5.3). */
PatchMatch searchEpipolar(const cv::Mat& image, const cv::Mat& patch, const EpipolarBand& band,
                          double threshold, NssdMethod method = NssdMethod::OpenCv);

/** Search a square of half-side @p radius_px around @p centre. */
PatchMatch searchSquare(const cv::Mat& image, const cv::Mat& patch, const Eigen::Vector2d& centre,
                        double radius_px, double threshold, NssdMethod method = NssdMethod::OpenCv);

}  // namespace mrolr::vision
