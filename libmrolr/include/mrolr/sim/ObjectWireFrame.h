#pragma once
/** The exact ground-truth wire-frame of an object definition (thesis 6.1: 3D lines and conics in
 * the object frame O, millimetres): the 12 edges of every box, the rims of every cylinder and cone
 * as circles, the four edge arcs of a cup handle, and every stroke of the letters as a line. */

#include <mrolr/model/WireFrame.h>
#include <mrolr/world/ObjectShape.h>

namespace mrolr::sim
{
/** Wire-frame of @p shape in O (mm), with its grasp point. Coincident circles (a rim shared by two
 * stacked parts of equal radius) are kept once. Ids run 1, 2, … over lines, then conics. */
model::WireFrame objectWireFrame(const world::ObjectShape& shape);

/** The in-plane axes of a box face (+x, -x, +y, -y, +z) in O: centre (mm), outward normal,
 * "right" and "up" as seen by a viewer facing the face. */
struct BoxFace
{
	Eigen::Vector3d centre_mm, normal, right, up;
};
/** Face @p face of box part @p part (see world::Marking). */
BoxFace boxFace(const world::ShapePart& part, const std::string& face);

/** Rotation about O's z by @p yaw_deg. */
Eigen::Matrix3d R_aboutZ(double yaw_deg);

}  // namespace mrolr::sim
