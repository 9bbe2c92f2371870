#pragma once
/** The UMI RTX's body as boxes fixed in the frames of its chain (RtxKinematics::linkFrames): the
 * column on the base A, the shoulder carriage at d1, the upper arm and forearm along their links,
 * the wrist stem and palm of the hand in G, and the calibration marker's stalk and plate
 * ([arm_marker]). One description serves the simulator, which draws it (sim/ArmVisual.h), and the
 * robot, which knows where its own arm is and so ignores what it sees of it (mission/SelfModel.h).
 * Sizes beyond the Denavit–Hartenberg lengths and the gripper's dimensions are assumptions (mm).
 * The finger plates move with the jaws and are not in the list; the palm spans the open jaws. */

#include <mrolr/arm/GraspFeasibility.h>
#include <mrolr/arm/MountCalibration.h>
#include <mrolr/arm/RtxKinematics.h>

#include <Eigen/Geometry>

#include <vector>

namespace mrolr::arm
{
/** An axis-aligned box of chain frame @p frame (0 = A, …, 6 = G), corners in mm. */
struct BodyBox
{
	int frame = 0;
	Eigen::Vector3d lo_mm = Eigen::Vector3d::Zero(), hi_mm = Eigen::Vector3d::Zero();
};

/** The RTX's fixed parts for the lengths of @p rtx, the gripper of @p grip and the marker @p m. */
std::vector<BodyBox> rtxBody(const RtxOptions& rtx, const GraspFeasibilityOptions& grip,
                             const MarkerOptions& m);

/** A box placed in some reference frame: centre and axes T_BoxInRef, half sizes (mm). */
struct PlacedBox
{
	Eigen::Isometry3d T_BoxInRef = Eigen::Isometry3d::Identity();
	Eigen::Vector3d half_mm = Eigen::Vector3d::Zero();
};

/** The boxes of @p body at joints @p j, the arm base at @p T_AinRef_mm. */
std::vector<PlacedBox> placeBody(const std::vector<BodyBox>& body, const RtxKinematics& kin,
                                 const RtxJoints& j, const Eigen::Isometry3d& T_AinRef_mm);

/** True when the segment @p a → @p b (Ref, mm) passes within @p margin_mm of @p box (the box
 * grown by the margin; slab test). */
bool segmentMeetsBox(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const PlacedBox& box,
                     double margin_mm);

}  // namespace mrolr::arm
