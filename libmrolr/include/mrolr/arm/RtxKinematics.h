#pragma once
/** Forward kinematics and the geometric Jacobian of the UMI RTX on
 * mrpt::kinematics::CKinematicChain (thesis B.3.1–B.3.2). Standard Denavit–Hartenberg links, A_i =
 * Rz(θi)·Tz(di)·Tx(ai)·Rx(αi): A1: θ = q1 (fixed), d = d1 (prismatic column);  A2: θ = q2, a = 254;
 * A3: θ = q3, a = 254; A4: θ = q4, α = 90°;  A5: θ = q5, α = 90°;  A6: θ = q6, d = 177. Frame 0 is
 * the arm base A: z up the column axis, x along the arm at q1 = q2 = q3 = 0. Frame 6 is the gripper
 * G at the grasp point: z6 the approach axis. Lengths in mm. */

#include <mrolr/arm/RtxJoints.h>
#include <mrolr/arm/RtxOptions.h>

#include <mrpt/kinematics/CKinematicChain.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <vector>

namespace mrolr::arm
{
/** 6×6 Jacobian: rows (v_x, v_y, v_z) in mm per unit and (ω_x, ω_y, ω_z) in rad per unit, in frame
 * 0; columns d1 (mm), q2..q6 (rad). */
using Jacobian6 = Eigen::Matrix<double, 6, 6>;

class RtxKinematics
{
 public:
	explicit RtxKinematics(const RtxOptions& options = RtxOptions());

	const RtxOptions& options() const { return options_; }

	/** T06 = A1·…·A6, the gripper frame in the arm base (mm), eq of B.3.2. */
	Eigen::Isometry3d T06(const RtxJoints& j) const;

	/** T0i for i = 0..6 (T00 = identity), from CKinematicChain::recomputeAllPoses. */
	std::vector<Eigen::Isometry3d> linkFrames(const RtxJoints& j) const;

	/** Geometric Jacobian of the gripper point with respect to [d1, q2..q6] (q1 fixed). */
	Jacobian6 jacobian(const RtxJoints& j) const;

	/** The chain set to @p j, lengths multiplied by @p scale (1 = mm; 0.001 for drawing in metres
	 * with CKinematicChain::getAs3DObject). */
	mrpt::kinematics::CKinematicChain chain(const RtxJoints& j, double scale = 1.0) const;

 private:
	RtxOptions options_;
};

}  // namespace mrolr::arm
