#pragma once
/** Poses of the things in a world: objects on tables, and W expressed in MRPT axes for rendering
 * and for the .3Dscene (MRPT: x forward, y left, z up = thesis z, x, y; geometry/Frames.h). */

#include <mrolr/world/World.h>

#include <mrpt/poses/CPose3D.h>

#include <Eigen/Geometry>

namespace mrolr::sim
{
/** Pose of a placed object's model frame O (z up, thesis 6.1) in W (thesis axes, metres): O's
 * origin on the table top at (x, z), O's z along W's y, and at yaw 0 O's x along W's z and O's y
 * along W's x; yaw turns about the vertical from W's z towards x. Throws world::WorldError if its
 * table does not exist. */
Eigen::Isometry3d T_OinW(const world::World& w, const world::PlacedObject& o);

/** The same pose with W in MRPT axes (O keeps its own axes), for the 3D scene. */
mrpt::poses::CPose3D objectPoseMrpt(const world::World& w, const world::PlacedObject& o);

/** Rotation about W's vertical (y) axis by @p yaw_rad, from z towards x. */
Eigen::Matrix3d R_aboutVertical(double yaw_rad);

}  // namespace mrolr::sim
