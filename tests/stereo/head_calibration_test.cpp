#include <mrolr/stereo/HeadCalibration.h>
#include <mrolr/stereo/Rectifier.h>

#include <gtest/gtest.h>
#include <opencv2/calib3d.hpp>

using namespace mrolr;

TEST(HeadCalibration, ReprojectsLikeTheHeadModelAndTriangulatesBack)
{
	const geometry::BiSightHead head;
	const geometry::HeadAngles a{0.2, -0.3, -0.05, 0.07};
	const stereo::StereoCalibration c = stereo::calibrationFromHead(head, a);
	const stereo::Rectifier rect(c);
	for (const Eigen::Vector3d& p_C0 : {Eigen::Vector3d(0.25, -0.4, 1.0), Eigen::Vector3d(0.1, -0.2, 1.4)})
	{
		const geometry::StereoPixels px = head.project(p_C0, a);
		const Eigen::Vector3d l = head.T_CamCvInC0(geometry::Side::Left, a).inverse() * p_C0 * 1000.0;
		const cv::Vec3d p_L(l.x(), l.y(), l.z());
		const cv::Vec3d p_R = c.R_RfromL * p_L + c.t_LinR_mm;
		EXPECT_NEAR(c.K_left(0, 0) * p_L[0] / p_L[2] + c.K_left(0, 2), px.uL, 1e-6);
		EXPECT_NEAR(c.K_right(0, 0) * p_R[0] / p_R[2] + c.K_right(0, 2), px.uR, 1e-6);
		EXPECT_NEAR(c.K_right(1, 1) * p_R[1] / p_R[2] + c.K_right(1, 2), px.vR, 1e-6);
		// rectified pixel and disparity of the point give it back in the thesis frame L (mm)
		const cv::Vec3d q = rect.R_RectFromL() * p_L;
		const double f = rect.focal_px();
		const cv::Point2d pp = rect.principalPoint_px();
		const Eigen::Vector3d back = rect.pointInLeftCamera(
			f * q[0] / q[2] + pp.x, f * q[1] / q[2] + pp.y, rect.disparityAtDepth(q[2]));
		const Eigen::Vector3d expected = head.T_LinC0(a).inverse() * p_C0 * 1000.0;
		EXPECT_LT((back - expected).norm(), 1e-6);
	}
	EXPECT_NEAR(c.baseline_mm(), 1000 * head.options().interocular_m, 40.0);
}
