#include <mrolr/stereo/Rectifier.h>

#include <opencv2/calib3d.hpp>
#include <opencv2/imgproc.hpp>

#include <stdexcept>

namespace mrolr::stereo
{
Rectifier::Rectifier(const StereoCalibration& c, const RectifyOptions& o) : size_(c.image_size)
{
	if (size_.width <= 0 || size_.height <= 0 || c.baseline_mm() <= 0)
		throw std::runtime_error(
		    "rectification needs a calibration with an image size and baseline");
	rect_size_ =
	    cv::Size(cvRound(size_.width * o.size_scale), cvRound(size_.height * o.size_scale));
	cv::Mat R1, R2, P1, P2, Q;
	cv::stereoRectify(cv::Mat(c.K_left), cv::Mat(c.D_left), cv::Mat(c.K_right), cv::Mat(c.D_right),
	                  size_, cv::Mat(c.R_RfromL), cv::Mat(c.t_LinR_mm), R1, R2, P1, P2, Q, 0,
	                  o.alpha, rect_size_);
	cv::initUndistortRectifyMap(cv::Mat(c.K_left), cv::Mat(c.D_left), R1, P1, rect_size_, CV_32FC1,
	                            map_lx_, map_ly_);
	cv::initUndistortRectifyMap(cv::Mat(c.K_right), cv::Mat(c.D_right), R2, P2, rect_size_,
	                            CV_32FC1, map_rx_, map_ry_);
	R1_ = R1;
	f_px_ = P1.at<double>(0, 0);
	cx_px_ = P1.at<double>(0, 2);
	cy_px_ = P1.at<double>(1, 2);
	doff_px_ = cx_px_ - P2.at<double>(0, 2);
	baseline_mm_ = -P2.at<double>(0, 3) / P2.at<double>(0, 0);
	if (std::abs(P2.at<double>(1, 3)) > 1e-9 || baseline_mm_ <= 0)
		throw std::runtime_error(
		    "rectification expects a horizontal baseline with the right camera "
		    "to the right of the left one");
	// p_L(thesis) = diag(-1,-1,1) · R1ᵀ · p_rect
	Eigen::Matrix3d R1t;
	for (int i = 0; i < 3; ++i)
		for (int j = 0; j < 3; ++j) R1t(i, j) = R1_(j, i);
	R_LthesisFromRect_ = Eigen::Vector3d(-1, -1, 1).asDiagonal() * R1t;
}

void Rectifier::rectify(const cv::Mat& left, const cv::Mat& right, cv::Mat& left_rect,
                        cv::Mat& right_rect) const
{
	if (left.size() != size_ || right.size() != size_)
		throw std::runtime_error("stereo images are " + std::to_string(left.cols) + "x" +
		                         std::to_string(left.rows) + " and " + std::to_string(right.cols) +
		                         "x" + std::to_string(right.rows) + " but the calibration is for " +
		                         std::to_string(size_.width) + "x" + std::to_string(size_.height));
	// replicated borders: no artificial step edge where the source image ends (validMasks)
	cv::remap(left, left_rect, map_lx_, map_ly_, cv::INTER_LINEAR, cv::BORDER_REPLICATE);
	cv::remap(right, right_rect, map_rx_, map_ry_, cv::INTER_LINEAR, cv::BORDER_REPLICATE);
}

void Rectifier::validMasks(int margin_px, cv::Mat& left_mask, cv::Mat& right_mask) const
{
	const cv::Mat all(size_, CV_8U, cv::Scalar(255));
	cv::remap(all, left_mask, map_lx_, map_ly_, cv::INTER_NEAREST, cv::BORDER_CONSTANT, 0);
	cv::remap(all, right_mask, map_rx_, map_ry_, cv::INTER_NEAREST, cv::BORDER_CONSTANT, 0);
	if (margin_px <= 0) return;
	const cv::Mat k =
	    cv::getStructuringElement(cv::MORPH_RECT, {2 * margin_px + 1, 2 * margin_px + 1});
	cv::erode(left_mask, left_mask, k, {-1, -1}, 1, cv::BORDER_CONSTANT, 0);
	cv::erode(right_mask, right_mask, k, {-1, -1}, 1, cv::BORDER_CONSTANT, 0);
}

Eigen::Vector3d Rectifier::pointInLeftCamera(double x_px, double y_px, double d_px) const
{
	const double z = f_px_ * baseline_mm_ / (d_px - doff_px_);
	const Eigen::Vector3d p_rect((x_px - cx_px_) * z / f_px_, (y_px - cy_px_) * z / f_px_, z);
	return R_LthesisFromRect_ * p_rect;
}

cv::Point2d Rectifier::leftPixelOf(const Eigen::Vector3d& p_L_mm) const
{
	const Eigen::Vector3d p = R_LthesisFromRect_.transpose() * p_L_mm;  // a rotation
	return {cx_px_ + f_px_ * p.x() / p.z(), cy_px_ + f_px_ * p.y() / p.z()};
}

double Rectifier::disparityOf(const Eigen::Vector3d& p_L_mm) const
{
	return disparityAtDepth((R_LthesisFromRect_.transpose() * p_L_mm).z());
}

Eigen::Vector3d Rectifier::leftRay(double x_px, double y_px) const
{
	return (R_LthesisFromRect_ * Eigen::Vector3d((x_px - cx_px_) / f_px_, (y_px - cy_px_) / f_px_, 1))
	    .normalized();
}

}  // namespace mrolr::stereo
