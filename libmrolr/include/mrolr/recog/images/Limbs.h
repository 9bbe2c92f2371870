#pragma once
/** Limbs (contour generators) of the bodies of revolution of a wire-frame model (beyond the
 * thesis; used by the verification in the images, ImageVerifier.h). A wire-frame holds a can's or
 * a bottle's rims, but the outline of its side is view-dependent: the lines along which the
 * sight rays graze the surface. Coaxial circles of a model define a body of revolution whose
 * profile r(z) is taken piecewise linear between them (cylinders and cone frusta); seen from a
 * camera centre, each frustum shows two straight generators on its outline, computed here and
 * sampled as extra edge samples. Model frame, millimetres. */

#include <mrolr/recog/Feature.h>

#include <Eigen/Core>

#include <vector>

namespace mrolr::recog
{
/** A point on a model edge and the edge's unit tangent there (model frame, mm). */
struct EdgeSample
{
	Eigen::Vector3d p_O, t_O;
	int feature = 0;  ///< index into the features sampled; -1 for a limb
};

/** A cylinder or cone frustum of a body of revolution: radius r0_mm at axial position z0_mm to
 * r1_mm at z1_mm (z0_mm < z1_mm). */
struct ProfileSegment
{
	double z0_mm = 0, r0_mm = 0, z1_mm = 0, r1_mm = 0;
};

/** A body of revolution: an axis (point, unit direction) and its profile along it, bottom up. */
struct RevolutionBody
{
	Eigen::Vector3d axis_point = Eigen::Vector3d::Zero();
	Eigen::Vector3d axis_dir = Eigen::Vector3d::UnitZ();
	std::vector<ProfileSegment> profile;  ///< at least one
};

/** How circles of a model are grouped into bodies of revolution. */
struct RevolutionGrouping
{
	double min_roundness = 0.8;    ///< semi-minor / semi-major axis of a circle
	double min_arc_fraction = 0.6; ///< arc length / circumference (a handle's arcs are half)
	double max_tilt_deg = 10;      ///< angle between a circle's normal and the body's axis
	double max_offset_frac = 0.2;  ///< centre's distance from the axis / the circle's radius
	/** Circles closer than this along the axis form one level: a rim measured twice, a step
	 * (a lid on a can: radii 33 and 28 at one height). Consecutive levels are joined by the
	 * frustum between their two circles of most similar radius. */
	double level_merge_mm = 4;
	double min_length_mm = 10;  ///< a body spans at least this along its axis
};

/** Bodies of revolution of @p features_O (model frame): groups of nearly circular, nearly full
 * conics that share an axis and span min_length_mm along it. Models without such circles (boxes,
 * letters, handle arcs) give none. */
std::vector<RevolutionBody> revolutionBodiesOf(const std::vector<Feature>& features_O,
                                               const RevolutionGrouping& g = {});

/** The two outline generators of each frustum of @p body seen from the camera centre @p c_O
 * (model frame, mm), sampled every @p spacing_mm (at least 2 per generator; tangents along the
 * generator; feature -1). A frustum seen along its axis from inside its cone shows no limb. */
std::vector<EdgeSample> limbSamples(const RevolutionBody& body, const Eigen::Vector3d& c_O,
                                    double spacing_mm);
/** limbSamples() appended to @p out (no allocation once @p out has grown: the sweep asks for
 * them at every pose). */
void appendLimbSamples(const RevolutionBody& body, const Eigen::Vector3d& c_O, double spacing_mm,
                       std::vector<EdgeSample>& out);

/** The outline generators themselves (end points), two per frustum that has them. */
std::vector<std::pair<Eigen::Vector3d, Eigen::Vector3d>> limbLines(const RevolutionBody& body,
                                                                   const Eigen::Vector3d& c_O);

/** True when @p p_O lies on the surface of one frustum of @p body: within @p tol_mm of its radius
 * at p's axial position, that position within the frustum's extent (± tol_mm). */
bool onSurface(const RevolutionBody& body, const Eigen::Vector3d& p_O, double tol_mm);

/** The terms of crossesSolid that depend only on the camera centre (model frame, mm). */
struct BodySight
{
	Eigen::Vector3d c_O, e1, e2;  ///< camera centre; two unit vectors normal to the axis
	Eigen::Vector2d w0;           ///< camera relative to the axis point, along e1, e2
	double cz = 0;                ///< ... and along the axis
	double r_max_mm = 0;          ///< the body's widest radius
};
BodySight bodySight(const RevolutionBody& body, const Eigen::Vector3d& c_O);

/** crossesSolid() with the camera's terms computed once (bodySight of the same body). */
bool crossesSolid(const RevolutionBody& body, const BodySight& sight, const Eigen::Vector3d& p_O,
                  double margin_mm);

/** True when the segment from @p c_O to @p p_O passes through the solid of @p body (the union of
 * its frusta, each shrunk by @p margin_mm radially): seen from @p c_O, @p p_O is behind it. Exact
 * for a body that is not convex (a bottle's neck above its shoulder), unlike a convex hull. */
bool crossesSolid(const RevolutionBody& body, const Eigen::Vector3d& c_O,
                  const Eigen::Vector3d& p_O, double margin_mm);

}  // namespace mrolr::recog
