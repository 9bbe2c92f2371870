#include <mrolr/base/TrajectoryPlanner.h>
#include <mrolr/geometry/IdealHead.h>
#include <mrolr/slam/HeadMeasurement.h>

#include <cmath>

namespace mrolr::slam
{
namespace
{
/** R_y(φ): columns are the vehicle's x (left), y (up), z (forward) axes in W. */
Eigen::Matrix3d vehicleRotation(double phi)
{
	const double c = std::cos(phi), s = std::sin(phi);
	Eigen::Matrix3d R;
	R << c, 0, s, 0, 1, 0, -s, 0, c;
	return R;
}
}  // namespace

Eigen::Vector3d headCentreInW(const Eigen::Vector3d& x_v, const HeadConstants& head)
{
	return {x_v[1], head.head_height_m, x_v[0]};
}

Eigen::Vector3d pointInHead(const Eigen::Vector3d& x_v, const Eigen::Vector3d& p_FinW,
                            const HeadConstants& head)
{
	return vehicleRotation(x_v[2]).transpose() * (p_FinW - headCentreInW(x_v, head));
}

Eigen::Vector3d predictMeasurement(const Eigen::Vector3d& x_v, const Eigen::Vector3d& p_FinW,
                                   const HeadConstants& head)
{
	return geometry::idealHeadMeasure(pointInHead(x_v, p_FinW, head), head.interocular_m);
}

PointInHeadJacobians pointInHeadJacobians(const Eigen::Vector3d& x_v, const Eigen::Vector3d& p_FinW,
                                          const HeadConstants& head)
{
	const Eigen::Vector3d m = pointInHead(x_v, p_FinW, head);
	const Eigen::Matrix3d Rt = vehicleRotation(x_v[2]).transpose();
	// ∂m/∂y = Rᵀ; ∂m/∂(z, x) = −Rᵀ columns of W's z and x; from eq 5.35
	// ∂m_x/∂φ = −(X − x) sin φ − (Z − z) cos φ = −m_z,  ∂m_z/∂φ = m_x.
	PointInHeadJacobians J;
	J.dm_dxv.col(0) = -Rt.col(2);
	J.dm_dxv.col(1) = -Rt.col(0);
	J.dm_dxv.col(2) = Eigen::Vector3d(-m.z(), 0, m.x());
	J.dm_dy = Rt;
	return J;
}

MeasurementJacobians measurementJacobians(const Eigen::Vector3d& x_v, const Eigen::Vector3d& p_FinW,
                                          const HeadConstants& head)
{
	const Eigen::Vector3d m = pointInHead(x_v, p_FinW, head);
	const Eigen::Matrix3d J = geometry::idealHeadJacobian(m, head.interocular_m);
	const auto Jm = pointInHeadJacobians(x_v, p_FinW, head);
	return {J * Jm.dm_dxv, J * Jm.dm_dy};
}

FeatureInitialisation initialiseFromMeasurement(const Eigen::Vector3d& x_v,
                                                const Eigen::Vector3d& h, const HeadConstants& head)
{
	const Eigen::Vector3d m = geometry::idealHeadInverse(h, head.interocular_m);
	const Eigen::Matrix3d R = vehicleRotation(x_v[2]);
	FeatureInitialisation out;
	out.p_FinW = headCentreInW(x_v, head) + R * m;
	// ∂y/∂(z, x): unit columns on W's z and x; ∂y/∂φ = ∂R/∂φ · m.
	const double c = std::cos(x_v[2]), s = std::sin(x_v[2]);
	out.dy_dxv.col(0) = Eigen::Vector3d(0, 0, 1);
	out.dy_dxv.col(1) = Eigen::Vector3d(1, 0, 0);
	out.dy_dxv.col(2) = Eigen::Vector3d(-s * m.x() + c * m.z(), 0, -c * m.x() - s * m.z());
	out.dy_dh = R * geometry::idealHeadInverseJacobian(h, head.interocular_m);
	return out;
}

Eigen::Vector3d measurementDifference(const Eigen::Vector3d& z, const Eigen::Vector3d& h)
{
	const Eigen::Vector3d d = z - h;
	return {base::wrapAngle(d[0]), base::wrapAngle(d[1]), base::wrapAngle(d[2])};
}

}  // namespace mrolr::slam
