#pragma once
/** What the robot knows of its own body in its cameras' view: the arm's boxes (arm/ArmBody.h) at
 * the joints its encoders report, placed by the nominal T_C0inA. What the head sees of its own
 * arm is no landmark, no obstacle and no scene: a point is "self" when the line of sight to it
 * from either camera passes within kSelfMargin_mm of an arm box (it lies on the arm, or behind
 * it). Navigation neither measures a feature it hides nor adds one on it; obstacle mode drops
 * the points on the arm (isOnArm()), since what the arm hides stereo does not measure. The margin covers the dock's error (±20 mm) and the cameras' travel with the head's
 * joints (a few cm). The arm is in view only while its platform is docked (setDocked(); thesis
 * 7.0): de-coupled, nothing the head sees is self. */
#include <mrolr/arm/ArmBody.h>
#include <mrolr/geometry/BiSightHead.h>
#include <mrolr/hw/Devices.h>

#include <Eigen/Geometry>

#include <array>
#include <vector>

namespace mrolr::mission
{
class SelfModel
{
 public:
	static constexpr double kSelfMargin_mm = 40;

	SelfModel(const arm::RtxOptions& rtx, const arm::GraspFeasibilityOptions& grip,
	          const arm::MarkerOptions& marker, const Eigen::Isometry3d& T_C0inA_mm,
	          const geometry::BiSightHead& head);

	/** The arm's joints now (its encoders; d1 mm, q deg). */
	void setJoints(const hw::ArmJoints& j);
	/** The arm's platform docked with the base (ArmDevice::dock()); false at the start. */
	void setDocked(bool docked) { docked_ = docked; }
	bool docked() const { return docked_; }

	/** True when @p p_inC0_m is on the docked arm or hidden by it from either camera. */
	bool isSelf(const Eigen::Vector3d& p_inC0_m) const;

	/** True when @p p_inC0_m lies within kSelfMargin_mm of an arm box (what stereo measures on
	 * the arm itself; what lies behind it, stereo does not see). */
	bool isOnArm(const Eigen::Vector3d& p_inC0_m) const;

	/** The same as isSelf with the arm docked at @p j instead (a pose it has not reached yet). */
	bool isSelfAt(const hw::ArmJoints& j, const Eigen::Vector3d& p_inC0_m) const;

	const std::vector<arm::PlacedBox>& boxesInC0() const { return boxes_; }

 private:
	std::vector<arm::BodyBox> body_;
	arm::RtxKinematics kin_;
	Eigen::Isometry3d T_AinC0_mm_;
	std::array<Eigen::Vector3d, 2> cameras_mm_;  ///< optic centres in C0, head at zero angles
	std::vector<arm::PlacedBox> boxes_;
	bool docked_ = false;
	bool hidden(const std::vector<arm::PlacedBox>& boxes, const Eigen::Vector3d& p_inC0_m) const;
};

}  // namespace mrolr::mission
