#pragma once
/** From the recognised object's pose to the arm (thesis 6.6–6.7). Frames: L the left camera, C0 the
 * head centre (fixed on the base), A the arm base (RtxKinematics frame 0), O the object model, G
 * the gripper at the grasp point. All translations in mm.
 *   T_OinC0 = T_LinC0(head angles) · T_OinL                     (6.6, eq 4.3.6)
 *   T_OinA  = T_C0inA · T_OinC0                                  (eq 6.7.1)
 *   T_C0inA = T_OinA · (T_OinC0)⁻¹  from a test object           (eq 6.7.2)
 *   T_GinA  = T_OinA · T_GinO, T_GinO from the model's grasp line (6.6) */

#include <mrolr/model/WireFrame.h>

#include <mrpt/config/CConfigFileBase.h>

#include <Eigen/Geometry>

#include <iosfwd>
#include <string>
#include <utility>
#include <vector>

namespace mrolr::arm
{
/** Where the docked arm stands relative to the head: section [arm_mount] of
 * config/arm_mount_parallel.ini or config/arm_mount_45.ini, key `T_C0inA` = the 12 numbers of the
 * 3×4 [R | t] row by row (mm). */
struct ArmMount
{
	Eigen::Isometry3d T_C0inA = Eigen::Isometry3d::Identity();

	/** Throws util::ConfigError naming file, section and key for a missing key, a wrong count of
	 * numbers or a 3×3 part that is not a rotation. */
	void loadFromConfigFile(const mrpt::config::CConfigFileBase& cfg, const std::string& section);
	static ArmMount fromFile(const std::string& path, const std::string& section = "arm_mount");
	void dump(std::ostream& out) const;
};

/** eq 6.7.1: the object in the arm base. */
Eigen::Isometry3d objectInArm(const Eigen::Isometry3d& T_C0inA, const Eigen::Isometry3d& T_OinC0);

/** eq 6.7.2: T_C0inA from one test object seen by the head (T_OinC0) and grasped by the arm
 * (T_OinA). */
Eigen::Isometry3d calibrateHeadInArm(const Eigen::Isometry3d& T_OinA,
                                     const Eigen::Isometry3d& T_OinC0);

/** eq 6.7.2 over several test objects (pairs T_OinA, T_OinC0): the rotation is the chordal mean
 * (nearest rotation to the sum of the per-object rotations), the translation the mean of
 * t_OinA − R·t_OinC0. Throws std::invalid_argument for an empty list. */
Eigen::Isometry3d calibrateHeadInArm(
    const std::vector<std::pair<Eigen::Isometry3d, Eigen::Isometry3d>>& T_OinA_T_OinC0);

/** T_GinO of a model's grasp line (position mm, yaw/pitch/roll as in GripperPose.h). */
Eigen::Isometry3d graspInObject(const model::Grasp& grasp);

/** T_GinA = T_C0inA · T_OinC0 · T_GinO: the gripper pose the arm must reach. */
Eigen::Isometry3d graspInArm(const Eigen::Isometry3d& T_C0inA, const Eigen::Isometry3d& T_OinC0,
                             const model::Grasp& grasp);

}  // namespace mrolr::arm
