#pragma once
/** What a closing parallel gripper meets: its two jaws (plates finger_width_mm wide along x_G and
 * finger_length_mm long along z_G, centred on the grasp point, closing along y_G) stop on the
 * object's solid, which slides between them. The reported jaw distance is then the solid's extent
 * along y_G inside the jaws' slab; 0 when nothing of the object is between them. Millimetres,
 * gripper frame G (arm/GraspFeasibility.h). */
#include <mrolr/world/ObjectShape.h>

#include <Eigen/Geometry>

namespace mrolr::sim
{
struct JawGeometry
{
	double opening_mm = 90;       ///< jaw distance of the open gripper
	double finger_length_mm = 40;  ///< along z_G
	double finger_width_mm = 20;   ///< along x_G
};

/** True when the point @p p_inO_mm lies inside the solid of @p shape (boxes, frusta, handle). */
bool insideShape(const world::ObjectShape& shape, const Eigen::Vector3d& p_inO_mm);

/** A box of G sampled for extentAlongYMm: x and z on nx × nz points over ±half_x_mm, ±half_z_mm,
 * y every 0.5 mm over ±half_y_mm. */
struct SlabSampling
{
	double half_x_mm = 10;
	int nx = 5;
	double half_y_mm = 45;
	double half_z_mm = 20;
	int nz = 9;
};

/** The extent along y_G (mm) of the part of @p shape inside the sampled box; 0 when none is. */
double extentAlongYMm(const world::ObjectShape& shape, const Eigen::Isometry3d& T_GinO_mm,
                      const SlabSampling& s);

/** Jaw distance (mm) on @p shape at @p T_OinG_mm; 0 when the jaws meet without touching it. */
double jawWidthMm(const world::ObjectShape& shape, const Eigen::Isometry3d& T_OinG_mm,
                  const JawGeometry& jaws);

}  // namespace mrolr::sim
