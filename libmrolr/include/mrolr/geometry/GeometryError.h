#pragma once
/** Exceptions of the geometry area. Each message says what was wrong with which input, so that an
 * app can print it as is. */

#include <stdexcept>

namespace mrolr::geometry
{
/** Base class of every geometric failure (bad input to a geometric model). */
class GeometryError : public std::runtime_error
{
 public:
	using std::runtime_error::runtime_error;
};

/** A point that is not in front of the camera it is projected into. */
class ProjectionError : public GeometryError
{
 public:
	using GeometryError::GeometryError;
};

/** A point the head cannot fixate: on the pan axis, too close, behind, or beyond a joint limit. */
class FixationError : public GeometryError
{
 public:
	using GeometryError::GeometryError;
};

/** Rays that cannot be triangulated: near-parallel, or meeting behind a camera. */
class TriangulationError : public GeometryError
{
 public:
	using GeometryError::GeometryError;
};

}  // namespace mrolr::geometry
