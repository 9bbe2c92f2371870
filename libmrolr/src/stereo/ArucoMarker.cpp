// One ArUco marker in a grey image, its centre where the diagonals cross.
#include <mrolr/stereo/ArucoMarker.h>

#include <opencv2/aruco.hpp>

#include <Eigen/Dense>

namespace mrolr::stereo
{
Eigen::Vector2d diagonalCrossing(const std::array<Eigen::Vector2d, 4>& c)
{
	// c0 + s (c2 − c0) = c1 + t (c3 − c1)
	Eigen::Matrix2d A;
	A.col(0) = c[2] - c[0];
	A.col(1) = c[1] - c[3];
	const Eigen::Vector2d st = A.colPivHouseholderQr().solve(c[1] - c[0]);
	return c[0] + st[0] * (c[2] - c[0]);
}

std::optional<ArucoSighting> findArucoMarker(const cv::Mat& grey, int id)
{
	const auto dict = cv::aruco::getPredefinedDictionary(cv::aruco::DICT_4X4_50);
	auto params = cv::aruco::DetectorParameters::create();
	params->cornerRefinementMethod = cv::aruco::CORNER_REFINE_SUBPIX;
	std::vector<std::vector<cv::Point2f>> corners;
	std::vector<int> ids;
	cv::aruco::detectMarkers(grey, dict, corners, ids, params);
	std::optional<ArucoSighting> found;
	for (size_t k = 0; k < ids.size(); ++k)
	{
		if (ids[k] != id) continue;
		if (found) return std::nullopt;  // twice in view: which one is ours is unknown
		ArucoSighting s;
		for (int i = 0; i < 4; ++i) s.corners_px[i] = {corners[k][i].x, corners[k][i].y};
		s.centre_px = diagonalCrossing(s.corners_px);
		found = s;
	}
	return found;
}

}  // namespace mrolr::stereo
