#pragma once
/** Epipolar rectification of a calibrated stereo pair (thesis 4.3.1, fig 4.3.1.1) with OpenCV's
 * stereoRectify: both images are re-projected onto a common plane parallel to the baseline so that
 * conjugate epipolar lines are the same image row. Rectified left pixel (x, y) with disparity
 * d = x_left − x_right (px) is the 3D point Z = f·B/(d − d0), X = (x − cx)·Z/f, Y = (y − cy)·Z/f in
 * the rectified left camera (OpenCV axes); pointInLeftCamera returns it in the thesis left camera
 * frame L of the unrectified left camera (x left, y up, z along the optic axis), millimetres. The
 * principal points of the rectified images differ by d0 = cx_left − cx_right (not forced to zero
 * disparity at infinity) so that verged cameras keep their common field of view. */

#include <mrolr/stereo/StereoCalibration.h>

#include <Eigen/Core>
#include <opencv2/core.hpp>

namespace mrolr::stereo
{
/** How much of the original images the rectified ones keep (cv::stereoRectify's alpha and new
 * image size). */
struct RectifyOptions
{
	double alpha = 0;       ///< 0: only valid pixels (zoomed in); 1: every source pixel kept
	double size_scale = 1;  ///< rectified image size = this × the calibration's image size
};

class Rectifier
{
 public:
	/** Computes the rectifying rotations and the remap tables (full-resolution, alpha = 0: only
	 * valid pixels). Throws std::runtime_error for a degenerate calibration. */
	explicit Rectifier(const StereoCalibration& calib, const RectifyOptions& options = {});

	/** Rectified left and right images (same type as the input). Throws std::runtime_error if a
	 * size differs from the calibration's image size. */
	void rectify(const cv::Mat& left, const cv::Mat& right, cv::Mat& left_rect,
	             cv::Mat& right_rect) const;

	/** Masks (CV_8U, 255 = a source pixel) of the rectified left and right images, shrunk by
	 * @p margin_px so that the border between image and no image is outside. */
	void validMasks(int margin_px, cv::Mat& left_mask, cv::Mat& right_mask) const;

	/** Size of the rectified images (px). */
	cv::Size rectifiedSize() const { return rect_size_; }

	/** 3D point (mm, thesis frame L of the original left camera) of rectified left pixel (x, y) px
	 * at disparity d px (d > 0). */
	Eigen::Vector3d pointInLeftCamera(double x_px, double y_px, double disparity_px) const;

	/** Rectified left pixel (px) of a 3D point @p p_L_mm (mm, thesis frame L, in front of the
	 * camera): the inverse of pointInLeftCamera for a given disparity. */
	cv::Point2d leftPixelOf(const Eigen::Vector3d& p_L_mm) const;

	/** Disparity (px) of a 3D point @p p_L_mm (mm, thesis frame L, in front of the camera). */
	double disparityOf(const Eigen::Vector3d& p_L_mm) const;

	/** Unit viewing ray (thesis frame L) of rectified left pixel (x, y). */
	Eigen::Vector3d leftRay(double x_px, double y_px) const;

	/** Disparity (px) of a point at depth z_mm along the rectified optic axis. */
	double disparityAtDepth(double z_mm) const { return f_px_ * baseline_mm_ / z_mm + doff_px_; }

	/** d0 = cx_left − cx_right of the rectified cameras (px): the disparity at infinite depth. */
	double disparityOffset_px() const { return doff_px_; }

	double focal_px() const { return f_px_; }
	double baseline_mm() const { return baseline_mm_; }
	cv::Point2d principalPoint_px() const { return {cx_px_, cy_px_}; }
	/** Rotation from the original left camera to the rectified left camera (OpenCV axes). */
	const cv::Matx33d& R_RectFromL() const { return R1_; }

 private:
	cv::Size size_, rect_size_;
	cv::Mat map_lx_, map_ly_, map_rx_, map_ry_;
	cv::Matx33d R1_;
	Eigen::Matrix3d R_LthesisFromRect_;
	double f_px_ = 0, cx_px_ = 0, cy_px_ = 0, baseline_mm_ = 0, doff_px_ = 0;
};

}  // namespace mrolr::stereo
