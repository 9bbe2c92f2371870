#pragma once
/** A rigid transform between the two length units of the project: metres where the world, the
 * head and the base meet (MRPT's unit), millimetres where the recogniser and the arm work (the
 * thesis's unit for models and grasps). The rotation is unchanged. */

#include <Eigen/Geometry>

namespace mrolr::geometry
{
/** @p T_m (translation in metres) with its translation in millimetres. */
inline Eigen::Isometry3d inMm(Eigen::Isometry3d T_m)
{
	T_m.translation() *= 1000.0;
	return T_m;
}

/** @p T_mm (translation in millimetres) with its translation in metres. */
inline Eigen::Isometry3d inMetres(Eigen::Isometry3d T_mm)
{
	T_mm.translation() /= 1000.0;
	return T_mm;
}
}  // namespace mrolr::geometry
