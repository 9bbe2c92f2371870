#include <mrolr/geometry/PinholeCamera.h>

#include <cmath>
#include <sstream>

namespace mrolr::geometry
{
Eigen::Vector2d PinholeCamera::project(const Eigen::Vector3d& m,
                                       Eigen::Matrix<double, 2, 3>* J) const
{
	if (!(m.z() > 0))
	{
		std::ostringstream msg;
		msg << "point (" << m.transpose() << ") is not in front of the camera (z <= 0)";
		throw ProjectionError(msg.str());
	}
	const double iz = 1.0 / m.z();
	if (J)
	{
		// d(u0 - fu x/z)/d(x, y, z) = (-fu/z, 0, fu x/z²), likewise for v.
		*J << -focal_px_u * iz, 0, focal_px_u * m.x() * iz * iz,  //
		    0, -focal_px_v * iz, focal_px_v * m.y() * iz * iz;
	}
	return {u0_px - focal_px_u * m.x() * iz, v0_px - focal_px_v * m.y() * iz};
}

Eigen::Vector3d PinholeCamera::backProject(const Eigen::Vector2d& uv) const
{
	return {(u0_px - uv.x()) / focal_px_u, (v0_px - uv.y()) / focal_px_v, 1.0};
}

Eigen::Matrix<double, 3, 2> PinholeCamera::backProjectJacobian() const
{
	Eigen::Matrix<double, 3, 2> J = Eigen::Matrix<double, 3, 2>::Zero();
	J(0, 0) = -1.0 / focal_px_u;
	J(1, 1) = -1.0 / focal_px_v;
	return J;
}

Eigen::Matrix3d PinholeCamera::calibrationMatrix() const
{
	Eigen::Matrix3d C;
	C << -focal_px_u, 0, u0_px,  //
	    0, -focal_px_v, v0_px,   //
	    0, 0, 1;
	return C;
}

Eigen::Matrix3d PinholeCamera::inverseCalibrationMatrix() const
{
	Eigen::Matrix3d Ci;
	Ci << -1.0 / focal_px_u, 0, u0_px / focal_px_u,  //
	    0, -1.0 / focal_px_v, v0_px / focal_px_v,    //
	    0, 0, 1;
	return Ci;
}

bool PinholeCamera::isInImage(const Eigen::Vector2d& uv) const
{
	return uv.x() >= 0 && uv.y() >= 0 && uv.x() < width_px && uv.y() < height_px;
}

mrpt::img::TCamera PinholeCamera::toTCamera() const
{
	mrpt::img::TCamera cam;
	cam.ncols = static_cast<uint32_t>(width_px);
	cam.nrows = static_cast<uint32_t>(height_px);
	cam.setIntrinsicParamsFromValues(focal_px_u, focal_px_v, u0_px, v0_px);
	cam.distortion = mrpt::img::DistortionModel::none;
	cam.dist.fill(0);
	return cam;
}

PinholeCamera PinholeCamera::fromTCamera(const mrpt::img::TCamera& cam)
{
	for (size_t i = 0; i < cam.dist.size(); ++i)
		if (cam.dist[i] != 0)
			throw GeometryError(
			    "TCamera has lens distortion (dist[" + std::to_string(i) +
			    "] != 0), which the distortion-free pinhole model cannot represent");
	PinholeCamera c;
	c.focal_px_u = cam.fx();
	c.focal_px_v = cam.fy();
	c.u0_px = cam.cx();
	c.v0_px = cam.cy();
	c.width_px = static_cast<int>(cam.ncols);
	c.height_px = static_cast<int>(cam.nrows);
	return c;
}

}  // namespace mrolr::geometry
