#pragma once
/** The UMI RTX drawn in the lab's scene at its current joints (world side): the body of
 * arm/ArmBody.h (column, carriage, links, wrist and hand, the marker's stalk), the ArUco code on
 * the marker's plate ([arm_marker], arm/MountCalibration.h) and the two finger plates at their
 * present separation. The rendered pairs see the arm wherever it is: it occludes what stands
 * behind it, and the verification view sees the gripper beside the object. */

#include <mrolr/arm/ArmBody.h>
#include <mrolr/arm/RtxKinematics.h>
#include <mrolr/sim/JawWidth.h>

#include <mrpt/opengl/CSetOfObjects.h>

#include <Eigen/Geometry>

#include <array>

namespace mrolr::sim
{
class ArmVisual
{
 public:
	/** @p finger_thickness_mm: each plate along y_G (GripperPhysicsOptions). */
	ArmVisual(const arm::RtxOptions& rtx, const arm::GraspFeasibilityOptions& grip,
	          double finger_thickness_mm, const arm::MarkerOptions& marker);

	/** The arm's parts, one set per chain frame; insert it into the scene once. */
	mrpt::opengl::CSetOfObjects::Ptr object() const { return root_; }

	/** Poses every part: the arm base at @p T_AinW_m (thesis axes, metres), joints @p j, the
	 * plates' inner faces @p separation_mm apart. */
	void update(const Eigen::Isometry3d& T_AinW_m, const arm::RtxJoints& j, double separation_mm);

 private:
	arm::RtxKinematics kin_;
	mrpt::opengl::CSetOfObjects::Ptr root_;
	std::array<mrpt::opengl::CSetOfObjects::Ptr, 7> frames_;  ///< parts fixed in frame i
	std::array<mrpt::opengl::CSetOfObjects::Ptr, 2> fingers_;  ///< plates, +y_G and −y_G
};

}  // namespace mrolr::sim
