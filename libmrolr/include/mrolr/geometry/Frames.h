#pragma once
/** The one place where the thesis frames meet MRPT's (../DESIGN.md "Frames and names").
 *
 *  thesis (W, C0, vehicle):  x left,    y up,   z forward;  vehicle state (z, x, φ), φ from z to x
 *  MRPT   (CPose2D/3D):      x forward, y left, z up;       CPose2D(x, y, φ), φ from x to y
 *
 * Both are right-handed and differ by a cyclic permutation of the axes: (x, y, z)_MRPT =
 * (z, x, y)_thesis. φ is the same angle in both (a left turn is positive). */

#include <mrpt/math/TPoint3D.h>
#include <mrpt/poses/CPose2D.h>
#include <mrpt/poses/CPose3D.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace mrolr::geometry
{
/** The rotation taking thesis-axes vectors to MRPT-axes vectors: [[0,0,1],[1,0,0],[0,1,0]]. */
Eigen::Matrix3d R_mrptFromThesis();

/** A point in thesis axes (W or C0, metres) as an MRPT point in the matching MRPT-axes frame. */
mrpt::math::TPoint3D pointToMrpt(const Eigen::Vector3d& p_thesis);
/** The inverse of pointToMrpt. */
Eigen::Vector3d pointFromMrpt(const mrpt::math::TPoint3D& p_mrpt);

/** A pose T_AinB whose frames A and B both use thesis axes, as the CPose3D of A in B with both
 * frames in MRPT axes: R' = P R Pᵀ, t' = P t with P = R_mrptFromThesis(). */
mrpt::poses::CPose3D poseToMrpt(const Eigen::Isometry3d& T_AinB_thesis);
/** The inverse of poseToMrpt. */
Eigen::Isometry3d poseFromMrpt(const mrpt::poses::CPose3D& pose_AinB_mrpt);

/** The pose of a camera given in the computer-vision convention (x right, y down, z forward, as
 * BiSightHead::T_CamCvInC0 returns) re-expressed with its parent frame in MRPT axes, ready for
 * MRPT's camera observations and renderers (CObservationImage::cameraPose uses the same camera
 * axes): R' = P R, t' = P t. */
mrpt::poses::CPose3D cameraPoseToMrpt(const Eigen::Isometry3d& T_CamCvInParent_thesis);
/** The inverse of cameraPoseToMrpt. */
Eigen::Isometry3d cameraPoseFromMrpt(const mrpt::poses::CPose3D& cameraPose_mrpt);

/** Vehicle state x_v = (z, x, φ) (metres, metres, radians; thesis 4.2.6) as MRPT's CPose2D(z, x,
 * φ). */
mrpt::poses::CPose2D vehicleToMrpt(const Eigen::Vector3d& xv_zxphi);
/** The inverse of vehicleToMrpt, with φ wrapped to (−π, π]. */
Eigen::Vector3d vehicleFromMrpt(const mrpt::poses::CPose2D& pose);

/** Pose of the head centre C0 in W (thesis axes) for vehicle state (z, x, φ) and head height M_h
 * above the ground plane in which W lies (eq 4.9, eq 5.50): rotation φ about the vertical axis,
 * translation (x, M_h, z). */
Eigen::Isometry3d T_C0inW(const Eigen::Vector3d& xv_zxphi, double head_height_m);

}  // namespace mrolr::geometry
