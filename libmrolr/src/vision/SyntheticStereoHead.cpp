#include <mrolr/vision/SyntheticStereoHead.h>
#include <mrolr/vision/VisionError.h>

#include <opencv2/imgproc.hpp>

#include <cmath>

namespace mrolr::vision
{
using geometry::HeadAngles;
using geometry::Side;

cv::Mat makeTexture(int size_px, std::uint64_t seed)
{
	if (size_px < 3 || size_px % 2 == 0) throw VisionError("makeTexture: size must be odd, >= 3");
	cv::RNG rng(seed);
	const int coarse = std::max(3, size_px / 2);
	cv::Mat small(coarse, coarse, CV_8UC1);
	rng.fill(small, cv::RNG::UNIFORM, 0, 256);
	cv::Mat tex;
	cv::resize(small, tex, cv::Size(size_px, size_px), 0, 0, cv::INTER_CUBIC);
	return tex;
}

SyntheticStereoHead::SyntheticStereoHead(const geometry::BiSightHead& head, double noise_sigma,
                                         std::uint64_t seed, int background)
    : head_(head), noise_sigma_(noise_sigma), rng_(seed), background_(background)
{
}

void SyntheticStereoHead::moveTo(const HeadAngles& angles)
{
	head_.checkJointLimits(angles);
	angles_ = angles;
}

namespace
{
/** Pastes @p tex with its centre at sub-pixel @p uv, warping only the affected rectangle. */
void paste(cv::Mat& image, const cv::Mat& tex, const Eigen::Vector2d& uv)
{
	const double half_u = 0.5 * (tex.cols - 1), half_v = 0.5 * (tex.rows - 1);
	const cv::Rect area =
	    cv::Rect(static_cast<int>(std::floor(uv.x() - half_u)) - 1,
	             static_cast<int>(std::floor(uv.y() - half_v)) - 1, tex.cols + 3, tex.rows + 3) &
	    cv::Rect(0, 0, image.cols, image.rows);
	if (area.empty()) return;
	const cv::Matx23d M(1, 0, uv.x() - half_u - area.x, 0, 1, uv.y() - half_v - area.y);
	cv::Mat dst = image(area);
	cv::warpAffine(tex, dst, M, dst.size(), cv::INTER_LINEAR, cv::BORDER_TRANSPARENT);
}
}  // namespace

cv::Mat SyntheticStereoHead::render(Side side, const HeadAngles& angles) const
{
	const auto& cam = head_.camera();
	cv::Mat image(cam.height_px, cam.width_px, CV_8UC1, cv::Scalar(background_));
	for (const auto& p : points_)
	{
		const Eigen::Vector3d m = head_.pointInCamera(side, p.p_inC0, angles);
		if (m.z() <= 1e-3) continue;
		paste(image, p.texture, cam.project(m));
	}
	return image;
}

StereoImages SyntheticStereoHead::grab()
{
	StereoImages out{render(Side::Left, angles_), render(Side::Right, angles_), angles_};
	for (cv::Mat* im : {&out.left, &out.right})
	{
		if (noise_sigma_ <= 0) continue;
		cv::Mat noise(im->size(), CV_16SC1);
		rng_.fill(noise, cv::RNG::NORMAL, 0, noise_sigma_);
		cv::Mat sum;
		cv::add(*im, noise, sum, cv::noArray(), CV_16SC1);
		sum.convertTo(*im, CV_8UC1);
	}
	return out;
}

}  // namespace mrolr::vision
