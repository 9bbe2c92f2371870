// Semi-global matching of a head stereo pair into points above the floor (thesis 5.8.1.2).
#include <mrolr/mission/ObstacleStereo.h>
#include <mrolr/stereo/HeadCalibration.h>

#include <opencv2/calib3d.hpp>
#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace mrolr::mission
{
namespace
{
cv::Mat grey(const cv::Mat& img)
{
	if (img.channels() == 1) return img;
	cv::Mat g;
	cv::cvtColor(img, g, img.channels() == 4 ? cv::COLOR_BGRA2GRAY : cv::COLOR_BGR2GRAY);
	return g;
}
/** Standard deviation of the grey levels in each @p block × @p block window. */
cv::Mat localStdDev(const cv::Mat& grey8, int block)
{
	cv::Mat f, mean, mean_sq;
	grey8.convertTo(f, CV_32F);
	cv::boxFilter(f, mean, CV_32F, cv::Size(block, block));
	cv::boxFilter(f.mul(f), mean_sq, CV_32F, cv::Size(block, block));
	cv::Mat var = cv::max(mean_sq - mean.mul(mean), 0.0), sd;
	cv::sqrt(var, sd);
	return sd;
}
/** |∇d| (px per px) by central differences; huge next to unmatched pixels (they are −1e9). */
cv::Mat disparityGradient(const cv::Mat& d)
{
	cv::Mat gx, gy, g;
	cv::Sobel(d, gx, CV_32F, 1, 0, 1, 0.5);
	cv::Sobel(d, gy, CV_32F, 0, 1, 1, 0.5);
	cv::magnitude(gx, gy, g);
	return g;
}
}  // namespace

ObstacleStereo::ObstacleStereo(const geometry::BiSightHead& head, const ObstacleOptions& options)
    : head_(head), o_(options)
{
}

const stereo::Rectifier& ObstacleStereo::rectifierFor(const geometry::HeadAngles& a)
{
	auto& r = rect_[{a.pan, a.tilt, a.verg_left, a.verg_right}];
	if (!r) r = std::make_unique<stereo::Rectifier>(stereo::calibrationFromHead(head_, a));
	return *r;
}

cv::Mat ObstacleStereo::disparityOf(const cv::Mat& left_rect, const cv::Mat& right_rect,
                                    const stereo::Rectifier& rect) const
{
	const double s = o_.image_scale;
	// disparity range (full resolution) of the depth range, scaled, rounded out to 16
	const double d_min = rect.disparityAtDepth(1000 * o_.max_depth_m) * s;
	const double d_max = rect.disparityAtDepth(1000 * o_.min_depth_m) * s;
	const int min_disp = static_cast<int>(std::floor(d_min));
	const int num_disp = 16 * static_cast<int>(std::ceil((d_max - min_disp) / 16.0));
	const int b = o_.block_size_px;
	auto sgbm = cv::StereoSGBM::create(min_disp, num_disp, b, 8 * b * b, 32 * b * b, 1, 63, 10, 100,
	                                   2, cv::StereoSGBM::MODE_SGBM);
	cv::Mat l, r, d16;
	cv::resize(left_rect, l, cv::Size(), s, s, cv::INTER_AREA);
	cv::resize(right_rect, r, cv::Size(), s, s, cv::INTER_AREA);
	// SGBM leaves the first min_disp + num_disp columns unmatched: pad both images on the left
	// so that the whole left image is searched, then cut the padding off again
	const int pad = std::max(0, min_disp + num_disp);
	cv::copyMakeBorder(l, l, 0, 0, pad, 0, cv::BORDER_REPLICATE);
	cv::copyMakeBorder(r, r, 0, 0, pad, 0, cv::BORDER_REPLICATE);
	sgbm->compute(l, r, d16);
	d16 = d16.colRange(pad, d16.cols).clone();
	cv::Mat d;
	d16.convertTo(d, CV_32F, 1.0 / 16);
	d.setTo(-1e9, d16 < 16 * min_disp);  // unmatched pixels
	// SGM's smoothing carries an edge's disparity into textureless surroundings: keep only
	// pixels whose block has texture
	d.setTo(-1e9, localStdDev(l.colRange(pad, l.cols), b) < o_.min_texture_grey);
	for (int y = 0; y < d.rows; ++y)  // matched into the padding: outside the right image
		for (int x = 0; x < d.cols; ++x)
			if (x - d.at<float>(y, x) < 0) d.at<float>(y, x) = -1e9;
	// "flying pixels": at a depth edge the matcher interpolates between the two depths, points
	// strung out along the rays; a surface's disparity changes slowly from pixel to pixel
	d.setTo(-1e9, disparityGradient(d) > o_.max_disparity_gradient);
	return d;
}

std::vector<Eigen::Vector3d> ObstacleStereo::pointsAboveFloor(const cv::Mat& left,
                                                              const cv::Mat& right,
                                                              const geometry::HeadAngles& angles)
{
	const auto& rect = rectifierFor(angles);
	cv::Mat lr, rr;
	rect.rectify(grey(left), grey(right), lr, rr);
	disparity_ = disparityOf(lr, rr, rect);
	const Eigen::Isometry3d T_LinC0 = head_.T_LinC0(angles);
	const double s = o_.image_scale, h = head_.options().head_height_m;
	std::vector<Eigen::Vector3d> out;
	for (int y = 0; y < disparity_.rows; ++y)
		for (int x = 0; x < disparity_.cols; ++x)
		{
			const float d = disparity_.at<float>(y, x) / float(s);
			if (d <= rect.disparityOffset_px()) continue;  // unmatched or at infinity
			// pixel centres of the scaled image in full-resolution pixels
			const double u = (x + 0.5) / s - 0.5, v = (y + 0.5) / s - 0.5;
			Eigen::Vector3d p = T_LinC0 * (rect.pointInLeftCamera(u, v, d) / 1000.0);
			p.y() += h;
			if (p.y() >= o_.min_height_m && p.y() <= o_.max_height_m) out.push_back(p);
		}
	return out;
}

}  // namespace mrolr::mission
