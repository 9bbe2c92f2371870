#pragma once
/** The 3D appearance of an object definition for rendering: MRPT OpenGL primitives in the object
 * frame O (z up), scaled from millimetres to metres. Boxes are CBox, cylinders and cones CCylinder,
 * the cup handle a ring of small boxes, and letters thin raised strokes. */

#include <mrolr/world/ObjectShape.h>

#include <mrpt/opengl/CSetOfObjects.h>

namespace mrolr::sim
{
/** Objects of @p shape in O (metres); place the result with setPose(objectPoseMrpt(...)). */
mrpt::opengl::CSetOfObjects::Ptr objectVisual(const world::ObjectShape& shape);

}  // namespace mrolr::sim
