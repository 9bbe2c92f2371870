#include "HeadMeasurement.h"

#include <mrolr/geometry/IdealHead.h>

#include <cmath>

namespace mrolr::slam::test
{
Eigen::Vector3d featureInC0(const Eigen::Vector3d& x_v, const Eigen::Vector3d& y)
{
	const double c = std::cos(x_v[2]), s = std::sin(x_v[2]);
	const double dX = y[0] - x_v[1], dZ = y[2] - x_v[0];
	return {dX * c - dZ * s, y[1], dX * s + dZ * c};
}

Eigen::Vector3d headMeasure(const Eigen::Vector3d& x_v, const Eigen::Vector3d& y, double I_m)
{
	return geometry::idealHeadMeasure(featureInC0(x_v, y), I_m);
}

Eigen::Matrix<double, 3, 6> headJacobian(const Eigen::Vector3d& x_v, const Eigen::Vector3d& y,
                                         double I_m)
{
	const Eigen::Vector3d m = featureInC0(x_v, y);
	const double c = std::cos(x_v[2]), s = std::sin(x_v[2]);
	Eigen::Matrix3d dm_dy;
	dm_dy << c, 0, -s, 0, 1, 0, s, 0, c;
	// m depends on (z, x) through −(x, z) and on φ by the rotation: ∂m/∂φ = (−m_z, 0, m_x).
	Eigen::Matrix3d dm_dxv;
	dm_dxv << s, -c, -m.z(), 0, 0, 0, -c, -s, m.x();
	const Eigen::Matrix3d dh_dm = geometry::idealHeadJacobian(m, I_m);
	Eigen::Matrix<double, 3, 6> J;
	J << dh_dm * dm_dxv, dh_dm * dm_dy;
	return J;
}

}  // namespace mrolr::slam::test
