// Image coordinates of a known point (thesis 4.2.3, eqs 4.22–4.24) with the Jacobian wrt the point.
#include <mrolr/geometry/BiSightHead.h>

namespace mrolr::geometry
{
StereoPixels BiSightHead::project(const Eigen::Vector3d& p_GinC0, const HeadAngles& angles,
                                  Eigen::Matrix<double, 4, 3>* J_wrt_point) const
{
	Eigen::Vector2d uv[2];
	int row = 0;
	for (Side side : {Side::Left, Side::Right})
	{
		const Eigen::Isometry3d T_camFromC0 = T_CamInC0(side, angles).inverse(Eigen::Isometry);
		Eigen::Matrix<double, 2, 3> J_pix;
		try
		{
			uv[row / 2] = camera_.project(T_camFromC0 * p_GinC0, &J_pix);
		}
		catch (const ProjectionError& e)
		{
			throw ProjectionError(std::string(side == Side::Left ? "left" : "right") +
			                      " camera: " + e.what());
		}
		// ∂m_cam/∂m_G is the rotation R_camFromC0 (eqs 4.22, 4.23).
		if (J_wrt_point) J_wrt_point->middleRows<2>(row) = J_pix * T_camFromC0.linear();
		row += 2;
	}
	return {uv[0].x(), uv[0].y(), uv[1].x(), uv[1].y()};
}

}  // namespace mrolr::geometry
