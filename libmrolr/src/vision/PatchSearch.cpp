#include <mrolr/vision/PatchSearch.h>
#include <mrolr/vision/VisionError.h>

#include <algorithm>
#include <cmath>

namespace mrolr::vision
{
namespace
{
/** Offset of the minimum of the parabola through (−1, a), (0, b), (+1, c), in [−0.5, 0.5]. */
double parabolaOffset(double a, double b, double c)
{
	const double den = a - 2 * b + c;
	if (den <= 1e-12) return 0;
	return std::clamp(0.5 * (a - c) / den, -0.5, 0.5);
}

/** Sub-pixel refinement of the map minimum at (x, y) along both axes. */
Eigen::Vector2d refine(const cv::Mat& map, int x, int y)
{
	Eigen::Vector2d d = Eigen::Vector2d::Zero();
	auto s = [&](int xx, int yy) { return static_cast<double>(map.at<float>(yy, xx)); };
	if (x > 0 && x + 1 < map.cols) d.x() = parabolaOffset(s(x - 1, y), s(x, y), s(x + 1, y));
	if (y > 0 && y + 1 < map.rows) d.y() = parabolaOffset(s(x, y - 1), s(x, y), s(x, y + 1));
	return d;
}

/** Best score of the map outside the patch-sized neighbourhood of (bx, by), region only. */
double secondScore(const cv::Mat& map, const cv::Rect& centres, const RegionTest& inside, int bx,
                   int by, int rx, int ry)
{
	double second = std::numeric_limits<double>::infinity();
	for (int y = 0; y < map.rows; ++y)
		for (int x = 0; x < map.cols; ++x)
		{
			if (std::abs(x - bx) <= rx && std::abs(y - by) <= ry) continue;
			if (!inside(Eigen::Vector2d(centres.x + x, centres.y + y))) continue;
			second = std::min(second, static_cast<double>(map.at<float>(y, x)));
		}
	return second;
}
}  // namespace

PatchMatch searchPatch(const cv::Mat& image, const cv::Mat& patch, const cv::Rect& box,
                       const RegionTest& inside, double threshold, NssdMethod method)
{
	if (patch.empty() || patch.rows % 2 == 0 || patch.cols % 2 == 0)
		throw VisionError("searchPatch: the saved patch must be non-empty with odd sides");
	const int rx = patch.cols / 2, ry = patch.rows / 2;
	const cv::Rect centres = box & cv::Rect(rx, ry, image.cols - 2 * rx, image.rows - 2 * ry);
	PatchMatch best;
	if (centres.empty()) return best;
	const cv::Rect roi(centres.x - rx, centres.y - ry, centres.width + 2 * rx,
	                   centres.height + 2 * ry);
	const cv::Mat map = nssdMap(image(roi), patch, method);
	int bx = -1, by = -1;
	for (int y = 0; y < map.rows; ++y)
		for (int x = 0; x < map.cols; ++x)
		{
			if (!inside(Eigen::Vector2d(centres.x + x, centres.y + y))) continue;
			++best.candidates;
			const double s = map.at<float>(y, x);
			if (s < best.score) best.score = s, bx = x, by = y;
		}
	if (bx < 0) return best;
	best.uv = Eigen::Vector2d(centres.x + bx, centres.y + by) + refine(map, bx, by);
	best.found = best.score < threshold;
	if (best.found) best.second_score = secondScore(map, centres, inside, bx, by, rx, ry);
	return best;
}

PatchMatch searchEllipse(const cv::Mat& image, const cv::Mat& patch, const ImageEllipse& region,
                         double threshold, NssdMethod method)
{
	return searchPatch(
	    image, patch, region.boundingBox(),
	    [&](const Eigen::Vector2d& uv) { return region.contains(uv); }, threshold, method);
}

PatchMatch searchEpipolar(const cv::Mat& image, const cv::Mat& patch, const EpipolarBand& band,
                          double threshold, NssdMethod method)
{
	return searchPatch(
	    image, patch, band.boundingBox(),
	    [&](const Eigen::Vector2d& uv) { return band.contains(uv); }, threshold, method);
}

PatchMatch searchSquare(const cv::Mat& image, const cv::Mat& patch, const Eigen::Vector2d& centre,
                        double radius_px, double threshold, NssdMethod method)
{
	const int r = static_cast<int>(std::ceil(radius_px));
	const cv::Rect box(static_cast<int>(std::lround(centre.x())) - r,
	                   static_cast<int>(std::lround(centre.y())) - r, 2 * r + 1, 2 * r + 1);
	return searchPatch(
	    image, patch, box, [](const Eigen::Vector2d&) { return true; }, threshold, method);
}

}  // namespace mrolr::vision
