#pragma once
/** The simulated UMI RTX arm: joint state within workspace limits, a gripper, and the grasped
 * object carried with the gripper. The arm kinematics belong to area `arm`; the simulator takes the
 * forward kinematics as a function so that it runs with any chain. */

#include <mrolr/hw/Devices.h>

#include <mrpt/config/CConfigFileBase.h>
#include <mrpt/opengl/COpenGLScene.h>

#include <Eigen/Geometry>

#include <functional>
#include <iosfwd>
#include <map>
#include <string>

namespace mrolr::sim
{
/** Section [sim_arm] of config/sim.ini: joint limits (d1 in mm, q1..q6 in degrees) and the grasp
 * capture radius. */
struct SimArmOptions
{
	hw::ArmJoints min{0, -180, -90, -160, -110, -90, -180};
	hw::ArmJoints max{915, 180, 90, 160, 110, 90, 180};
	/** Closing the gripper catches the nearest object whose origin is this close to the grasp
	 * point and that the jaws touch (JawWidth callback > 0). */
	double grasp_radius_m = 0.05;
	double open_width_mm = 90;  ///< jaw distance of the open gripper (the RTX's 90 mm)

	void loadFromConfigFile(const mrpt::config::CConfigFileBase& cfg, const std::string& section);
	void dump(std::ostream& out) const;
};

/** The jaw distance (mm) when the gripper closes on object @p name at @p T_OinG (m); 0 when the
 * jaws meet without touching it. */
using JawWidth = std::function<double(const std::string& name, const Eigen::Isometry3d& T_OinG)>;

class SimArm : public hw::ArmDevice
{
 public:
	/** @p T_GinW: gripper pose in W (thesis axes) for joints; @p objects: name → T_OinW (the arm
	 * updates the grasped one); @p scene: if given, its "object.<name>" visual follows;
	 * @p jaw_width: the width the closed jaws report on a caught object (unset: 0). */
	SimArm(std::function<Eigen::Isometry3d(const hw::ArmJoints&)> T_GinW, const SimArmOptions& o,
	       std::map<std::string, Eigen::Isometry3d>& objects,
	       mrpt::opengl::COpenGLScene* scene = nullptr, JawWidth jaw_width = {});

	void moveTo(const hw::ArmJoints& joints) override;
	hw::ArmJoints joints() const override { return joints_; }
	void setGripper(bool closed) override;
	bool gripperClosed() const override { return closed_; }
	double gripperWidthMm() const override;
	/** Name of the object in the gripper, or "". */
	const std::string& grasped() const { return grasped_; }
	/** The arm's base moved (it is mounted on the robot): the grasped object follows the gripper. */
	void baseMoved() { carry(); }

 private:
	void carry();

	std::function<Eigen::Isometry3d(const hw::ArmJoints&)> T_GinW_;
	SimArmOptions options_;
	std::map<std::string, Eigen::Isometry3d>& objects_;
	mrpt::opengl::COpenGLScene* scene_;
	JawWidth jaw_width_;
	hw::ArmJoints joints_{};
	bool closed_ = false;
	std::string grasped_;
	Eigen::Isometry3d T_OinG_ = Eigen::Isometry3d::Identity();
};

}  // namespace mrolr::sim
