#pragma once
/** The simulated UMI RTX arm: joint state within workspace limits, a gripper, and the grasped
 * object carried with the gripper. The arm kinematics belong to area `arm`; the simulator takes the
 * forward kinematics as a function so that it runs with any chain. */

#include <mrolr/hw/Devices.h>
#include <mrolr/sim/GripperPhysics.h>

#include <mrpt/config/CConfigFileBase.h>
#include <mrpt/opengl/COpenGLScene.h>

#include <Eigen/Geometry>

#include <functional>
#include <iosfwd>
#include <map>
#include <string>

namespace mrolr::sim
{
/** Section [sim_arm] of a mission file or config/sim.ini: joint limits (d1 in mm, q1..q6 in
 * degrees) and the open jaw distance. */
struct SimArmOptions
{
	/** The RTX's ranges (config/arm_rtx.ini's limits in counts), so that an arm simulated without
	 * a [sim_arm] section (mission_hw.ini with --serial-emulation) accepts what the robot plans. */
	hw::ArmJoints min{-30, -180, -91, -181, -111, -181, -181};
	hw::ArmJoints max{925, 180, 91, 151, 111, 181, 181};
	double open_width_mm = 90;  ///< jaw distance of the open gripper (the RTX's 90 mm)
	/** The dock's error: the arm base stands off the nominal [arm_mount] T_C0inA by a rigid offset
	 * drawn once per run from [mission] seed, each translation within ±mount_error_mm and each
	 * rotation (about A's axes) within ±mount_error_deg. The robot does not know it. */
	double mount_error_mm = 0;
	double mount_error_deg = 0;
	bool drawn = false;  ///< key draw_arm: the arm appears in the rendered pairs (ArmVisual.h)

	void loadFromConfigFile(const mrpt::config::CConfigFileBase& cfg, const std::string& section);
	void dump(std::ostream& out) const;
};

class SimArm : public hw::ArmDevice
{
 public:
	/** @p T_GinW: gripper pose in W (thesis axes) for joints; @p objects: name → T_OinW (the arm
	 * updates the grasped one); @p scene: if given, its "object.<name>" visual follows;
	 * @p physics: what the fingers meet on the way and whether a closing grip holds
	 * (GripperPhysics.h); without it the gripper closes on nothing. */
	SimArm(std::function<Eigen::Isometry3d(const hw::ArmJoints&)> T_GinW, const SimArmOptions& o,
	       std::map<std::string, Eigen::Isometry3d>& objects,
	       mrpt::opengl::COpenGLScene* scene = nullptr, GripperPhysics* physics = nullptr);

	/** Moves in joint space along the straight line to @p joints, the gripper tested against the
	 * world every GripperPhysicsOptions::motion_step_mm; throws hw::ArmBlocked (the arm left at
	 * the last free pose) when a finger meets a table. */
	void moveTo(const hw::ArmJoints& joints) override;
	hw::ArmJoints joints() const override { return joints_; }
	void setGripper(bool closed) override;
	bool gripperClosed() const override { return closed_; }
	double gripperWidthMm() const override;
	/** The platform starts de-coupled (thesis 7.0); de-coupling with an object in the jaws is
	 * refused, since the object would leave with the arm. Undocked, the arm is not in the world:
	 * not drawn, not moved, not gripping. */
	void dock(bool docked) override;
	bool docked() const override { return docked_; }
	/** Name of the object in the gripper, or "". */
	const std::string& grasped() const { return grasped_; }
	/** Called with the held object's name when the jaws open on it (before it is let go). */
	void onRelease(std::function<void(const std::string&)> f) { on_release_ = std::move(f); }
	/** The arm's base moved (it is mounted on the robot): the grasped object follows the gripper. */
	void baseMoved() { carry(); }

	/** The jaw separation the fingers have now (mm). */
	double separationMm() const;

 private:
	void carry();
	/** Throws std::logic_error naming @p what when the platform is not docked. */
	void requireDocked(const char* what) const;

	std::function<Eigen::Isometry3d(const hw::ArmJoints&)> T_GinW_;
	SimArmOptions options_;
	std::map<std::string, Eigen::Isometry3d>& objects_;
	mrpt::opengl::COpenGLScene* scene_;
	/** Tested poses of the move to @p joints (1 without physics). */
	int motionSteps(const hw::ArmJoints& joints) const;
	GripperPhysics* physics_;
	std::function<void(const std::string&)> on_release_;
	hw::ArmJoints joints_{};
	bool closed_ = false;
	bool docked_ = false;
	std::string grasped_;
	double width_mm_ = 0;  ///< jaw distance on the caught object
	Eigen::Isometry3d T_OinG_ = Eigen::Isometry3d::Identity();
};

}  // namespace mrolr::sim
