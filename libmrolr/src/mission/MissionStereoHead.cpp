// The mission's head as the vision area's stereo head (navigation measurements from images).
#include <mrolr/mission/MissionStereoHead.h>

#include <opencv2/imgproc.hpp>

#include <chrono>

namespace mrolr::mission
{
namespace
{
cv::Mat grey(const mrpt::img::CImage& img)
{
	cv::Mat m = img.asCvMat<cv::Mat>(mrpt::img::SHALLOW_COPY), g;
	if (m.channels() == 1) return m.clone();
	cv::cvtColor(m, g, cv::COLOR_BGR2GRAY);
	return g;
}
}  // namespace

void MissionStereoHead::moveTo(const geometry::HeadAngles& angles)
{
	head_.moveTo(angles);
}

vision::StereoImages MissionStereoHead::grab()
{
	const auto t0 = std::chrono::steady_clock::now();
	const hw::StereoImages im = head_.grab();
	vision::StereoImages out{grey(im.left), grey(im.right), im.angles};
	grab_s_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
	++grabs_;
	return out;
}

}  // namespace mrolr::mission
