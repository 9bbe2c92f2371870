#include <mrolr/stereo/HeadCalibration.h>

namespace mrolr::stereo
{
StereoCalibration calibrationFromHead(
	const geometry::BiSightHead& head, const geometry::HeadAngles& angles)
{
	const auto& o = head.options();
	StereoCalibration c;
	c.image_size = cv::Size(o.image_width_px, o.image_height_px);
	c.K_left = c.K_right = cv::Matx33d(o.focal_px_u, 0, o.u0_px, 0, o.focal_px_v, o.v0_px, 0, 0, 1);
	// p_Rcv = T_RcvInC0⁻¹ · T_LcvInC0 · p_Lcv (metres in the geometry library)
	const Eigen::Isometry3d T = head.T_CamCvInC0(geometry::Side::Right, angles).inverse() *
								head.T_CamCvInC0(geometry::Side::Left, angles);
	for (int i = 0; i < 3; ++i)
	{
		for (int j = 0; j < 3; ++j) c.R_RfromL(i, j) = T.linear()(i, j);
		c.t_LinR_mm[i] = 1000.0 * T.translation()[i];
	}
	return c;
}

}  // namespace mrolr::stereo
