#pragma once
/** The same RTX chain in Orocos KDL, for cross-checking RtxKinematics and the inverse solvers with
 * an independent implementation (KDL's recursive FK, Jacobian and LMA solvers). Joints of the KDL
 * chain: [d1, q2, q3, q4, q5, q6]; q1 is baked in as a fixed rotation. */

#include <mrolr/arm/RtxJoints.h>
#include <mrolr/arm/RtxOptions.h>

#include <kdl/chain.hpp>
#include <kdl/frames.hpp>
#include <kdl/jntarray.hpp>

#include <Eigen/Geometry>

namespace mrolr::arm
{
/** KDL chain of the RTX with lengths multiplied by @p scale (1 = mm, 0.001 = metres), built from
 * KDL::Frame::DH (standard Denavit–Hartenberg) with q1 = @p q1_rad fixed. */
KDL::Chain rtxKdlChain(const RtxOptions& o, double q1_rad, double scale = 1.0);

/** [d1·scale, q2..q6] of @p j as a KDL joint array. */
KDL::JntArray toKdl(const RtxJoints& j, double scale = 1.0);

/** Inverse of toKdl; q1 = @p q1_rad. */
RtxJoints fromKdl(const KDL::JntArray& q, double q1_rad, double scale = 1.0);

/** Frame conversions; the KDL translation is multiplied by @p scale going to KDL and divided coming
 * back. */
KDL::Frame toKdl(const Eigen::Isometry3d& T, double scale = 1.0);
Eigen::Isometry3d fromKdl(const KDL::Frame& F, double scale = 1.0);

}  // namespace mrolr::arm
