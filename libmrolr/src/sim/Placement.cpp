#include <mrolr/geometry/Frames.h>
#include <mrolr/sim/Placement.h>

#include <cmath>

namespace mrolr::sim
{
Eigen::Matrix3d R_aboutVertical(double yaw_rad)
{
	return Eigen::AngleAxisd(yaw_rad, Eigen::Vector3d::UnitY()).toRotationMatrix();
}

Eigen::Isometry3d T_OinW(const world::World& w, const world::PlacedObject& o)
{
	const world::Table* t = w.findTable(o.table);
	if (!t)
		throw world::WorldError(w.path + ": object '" + o.name + "' on unknown table '" + o.table +
		                        "'");
	Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
	// O's (x, y, z) = W's (z, x, y) at yaw 0: the transpose of geometry::R_mrptFromThesis
	T.linear() =
	    R_aboutVertical(o.yaw_deg * M_PI / 180.0) * geometry::R_mrptFromThesis().transpose();
	T.translation() = Eigen::Vector3d(o.x_m, w.room.floorY() + t->top_height_m, o.z_m);
	return T;
}

mrpt::poses::CPose3D objectPoseMrpt(const world::World& w, const world::PlacedObject& o)
{
	return geometry::cameraPoseToMrpt(T_OinW(w, o));
}

}  // namespace mrolr::sim
