#include <mrolr/model/TurntableBuilderImages.h>

#include <opencv2/calib3d.hpp>
#include <opencv2/imgproc.hpp>

#include <cmath>

namespace mrolr::model
{
ViewEdges makeViewEdges(const cv::Mat& left_grey, const stereo::StereoCalibration& calib,
                        const Eigen::Isometry3d& T_LinT_mm, double angle_deg)
{
	ViewEdges v;
	cv::Mat smooth, gx, gy;
	cv::GaussianBlur(left_grey, smooth, cv::Size(3, 3), 0.8);
	cv::Sobel(smooth, gx, CV_32F, 1, 0, 3, 0.125);  // 1/8: grey levels per pixel
	cv::Sobel(smooth, gy, CV_32F, 0, 1, 3, 0.125);
	cv::magnitude(gx, gy, v.gradient);
	const Eigen::Isometry3d T_OinT(
	    Eigen::AngleAxisd(angle_deg * M_PI / 180, Eigen::Vector3d::UnitZ()));
	v.T_OinL = T_LinT_mm.inverse() * T_OinT;
	v.K = calib.K_left;
	v.D = calib.D_left;
	return v;
}

double imageEdgeShare(const std::vector<FeatureSample>& samples, const ViewEdges& view,
                      double min_gradient)
{
	std::vector<cv::Point3d> p_cv;  // OpenCV camera axes: x right, y down (thesis L: left, up)
	for (const auto& s : samples)
	{
		const Eigen::Vector3d p = view.T_OinL * s.p;
		if (p.z() > 1) p_cv.emplace_back(-p.x(), -p.y(), p.z());
	}
	if (p_cv.empty()) return 0.0;
	std::vector<cv::Point2d> px;
	cv::projectPoints(p_cv, cv::Vec3d(0, 0, 0), cv::Vec3d(0, 0, 0), view.K, view.D, px);
	size_t n = 0;
	const cv::Rect inner(1, 1, view.gradient.cols - 2, view.gradient.rows - 2);
	for (const auto& q : px)
	{
		const cv::Point c(static_cast<int>(std::lround(q.x)), static_cast<int>(std::lround(q.y)));
		if (!inner.contains(c)) continue;
		double best = 0;
		cv::minMaxLoc(view.gradient(cv::Rect(c.x - 1, c.y - 1, 3, 3)), nullptr, &best);
		n += best >= min_gradient;
	}
	return static_cast<double>(n) / samples.size();
}

}  // namespace mrolr::model
