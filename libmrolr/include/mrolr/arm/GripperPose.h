#pragma once
/** Position and yaw, pitch, roll of a gripper frame G in a frame F (F = arm base A, or the object O
 * for a model's grasp line, thesis 6.6). Angles in degrees, position in mm. The convention follows
 * the RTX wrist (B.3.1, compute_xyz):
 *  - the approach axis z_G = (cos yaw · cos pitch, sin yaw · cos pitch, −sin pitch): yaw is its
 *    heading from x_F towards y_F (counter-clockwise seen from +z_F), pitch its angle below the
 *    x_F–y_F plane (pitch = 90° points down −z_F);
 *  - at roll = 0, x_G lies in the vertical plane through z_G, on the +z_F side, and y_G = z_G × x_G
 *    is horizontal; roll turns x_G towards y_G about z_G.
 * Equivalently R_GinF = Rz(yaw) · Ry(90° + pitch) · Rz(180° + roll). For the RTX with q1 = 0 this
 * means yaw = q2 + q3 + q4, pitch = 90° − q5, roll = q6. */

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <string>

namespace mrolr::arm
{
struct GripperPose
{
	Eigen::Vector3d p_mm = Eigen::Vector3d::Zero();
	double yaw_deg = 0;
	double pitch_deg = 0;
	double roll_deg = 0;
};

/** R_GinF of the convention above (angles in degrees). */
Eigen::Matrix3d rotationFromYawPitchRoll(double yaw_deg, double pitch_deg, double roll_deg);

/** T_GinF of @p g. */
Eigen::Isometry3d poseFromGripper(const GripperPose& g);

/** Inverse of poseFromGripper: yaw in (−180, 180], pitch in [−90, 90], roll in (−180, 180]. At
 * pitch = ±90° (approach vertical) yaw and roll are not separable: yaw is set to 0. */
GripperPose gripperFromPose(const Eigen::Isometry3d& T_GinF);

/** "x,y,z,yaw,pitch,roll" (mm, degrees) → GripperPose; throws PoseInputError naming @p what. */
GripperPose parseGripper(const std::string& text, const std::string& what);

}  // namespace mrolr::arm
