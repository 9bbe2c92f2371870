#include <mrolr/stereo/EdgelSupport.h>

#include <algorithm>
#include <cmath>

namespace mrolr::stereo
{
double edgelSupport(const std::vector<EdgeString>& strings, cv::Point2d a, cv::Point2d b,
                    double max_angle_deg, double radius_px)
{
	const double len = cv::norm(b - a);
	if (len < 2) return 0;
	const cv::Point2d u = (b - a) / len;
	const double sin_max = std::sin(std::clamp(max_angle_deg, 0.0, 90.0) * M_PI / 180);
	const cv::Rect2d box(std::min(a.x, b.x) - radius_px, std::min(a.y, b.y) - radius_px,
	                     std::abs(b.x - a.x) + 2 * radius_px, std::abs(b.y - a.y) + 2 * radius_px);
	std::vector<cv::Point2d> near;  // edgels in the segment's box, along its direction
	for (const auto& s : strings)
		for (const auto& e : s)
			if (box.contains(e.p) && std::abs(e.tangent().cross(u)) <= sin_max + 1e-12)
				near.push_back(e.p);
	const int n = static_cast<int>(len);
	int hit = 0;
	for (int k = 0; k <= n; ++k)
	{
		const cv::Point2d q = a + u * (len * k / n);
		hit += std::any_of(near.begin(), near.end(),
		                   [&](const cv::Point2d& p) { return cv::norm(p - q) <= radius_px; });
	}
	return static_cast<double>(hit) / (n + 1);
}

}  // namespace mrolr::stereo
