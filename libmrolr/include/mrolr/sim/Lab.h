#pragma once
/** The simulated lab, the world side of a mission: the true base (SimBase), the objects' true
 * poses, the head that renders the lab's stereo pairs (with image noise) and the RTX arm mounted
 * on the base at the physical T_C0inA. It offers the robot its devices (hw:: interfaces) and keeps
 * the truth to itself: the true poses, what the gripper holds and a log for eval. Both the
 * in-process mission (`driver = sim`) and the device emulators of `mrolr-serial emulate` serve
 * these devices. W: x left, y up, z forward, metres. */
#include <mrolr/arm/GraspChain.h>
#include <mrolr/arm/GraspFeasibility.h>
#include <mrolr/arm/MountCalibration.h>
#include <mrolr/arm/RtxOptions.h>
#include <mrolr/base/LabmateModel.h>
#include <mrolr/geometry/BiSightOptions.h>
#include <mrolr/hw/Devices.h>
#include <mrolr/sim/GripperPhysics.h>
#include <mrolr/sim/SimArm.h>
#include <mrolr/sim/SimBase.h>
#include <mrolr/sim/StereoRenderer.h>
#include <mrolr/world/ObjectShape.h>
#include <mrolr/world/World.h>

#include <mrpt/config/CConfigFileBase.h>

#include <Eigen/Geometry>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <vector>

namespace mrolr::sim
{
/** Everything the simulated lab is built from. loadFromConfigFile() reads the world side's
 * sections of a mission file: `[simulator] world_file` (or the one given), the robot's physical
 * build from the files `[files]` names (labmate, bisight, arm) and `[arm_mount] T_C0inA`,
 * `[sim_base]`, `[sim_arm]`, `[sim_gripper]`, `[sim_render]` (all keys optional) and `[mission] seed`, from which
 * every random draw of the world follows. */
struct LabOptions
{
	std::string world_file;
	world::World world;
	base::LabmateOptions labmate;
	geometry::BiSightOptions bisight;
	arm::RtxOptions rtx;
	arm::GraspFeasibilityOptions gripper;  ///< the gripper's opening and fingers
	arm::ArmMount mount;                   ///< nominal T_C0inA of the arm on the base (mm)
	arm::MarkerOptions marker;             ///< the hand's calibration ball, drawn ([arm_marker])
	SimBaseOptions base;
	SimArmOptions arm;
	GripperPhysicsOptions gripper_physics;
	RenderOptions render;
	double head_move_time_s = 2.0;  ///< settle time a head move reports
	unsigned seed = 1;

	/** @p base_dir resolves relative file names; @p world_file, if not empty, replaces
	 * `[simulator] world_file`. Throws util::ConfigError / world::WorldError naming the key. */
	static LabOptions load(const mrpt::config::CConfigFileBase& cfg, const std::string& base_dir,
	                       const std::string& world_file = "");
	/** True when @p cfg names a world (`[simulator] world_file`). */
	static bool namesWorld(const mrpt::config::CConfigFileBase& cfg);
};

/** The instance name → pose (T_OinW, m) of every placed object of @p w. */
std::map<std::string, Eigen::Isometry3d> placedObjectPoses(const world::World& w);

/** What the world side logs while the robot runs, for eval. */
struct TruthLog
{
	struct Step
	{
		double time_s = 0;  ///< the base device's time after the step
		Eigen::Vector3d xv_zxphi = Eigen::Vector3d::Zero();
	};
	struct Frame
	{
		uint64_t frame = 0;  ///< the camera's frame counter (hw::StereoImages::frame)
		Eigen::Isometry3d T_C0inW = Eigen::Isometry3d::Identity();
		std::map<std::string, Eigen::Isometry3d> T_OinW;  ///< every object at that moment
	};
	std::vector<Step> steps;  ///< the start pose, then one per base step
	std::vector<Frame> frames;
};

class Lab
{
 public:
	/** The base starts at the world's first waypoint, the objects where the world places them. */
	explicit Lab(const LabOptions& o);
	~Lab();
	Lab(const Lab&) = delete;
	Lab& operator=(const Lab&) = delete;

	/** The robot's devices. */
	hw::BaseDevice& base();
	hw::HeadDevice& head();
	hw::ArmDevice& arm();

	/** Truth, world side only. */
	Eigen::Vector3d truePose() const { return base_.truePose(); }
	Eigen::Isometry3d trueC0() const;
	/** The arm base's true place: the nominal T_C0inA off by the dock's error (mm). */
	const Eigen::Isometry3d& trueMount() const { return T_C0inA_true_mm_; }
	/** The arm base A in W now (thesis axes, metres). */
	Eigen::Isometry3d T_AinW() const;
	const SimArm& simArm() const { return *arm_; }
	const std::map<std::string, Eigen::Isometry3d>& objectPoses() const { return poses_; }
	/** Instance in the gripper, "" if none. */
	const std::string& held() const { return arm_->grasped(); }
	/** Instances the gripper let go of over the robot's deck: they ride on it. */
	const std::set<std::string>& onBoard() const { return on_board_; }
	/** The deck's top face in W now (the base's physical deck, [labmate] deck_height_m). */
	DeckSupport deck() const;
	/** What the gripper did to the world, in order (pushes, falls, grips, the table). */
	const std::vector<GripperEvent>& gripperEvents() const { return gripper_->events(); }
	/** The model of instance @p name ("" if unknown). */
	std::string modelOf(const std::string& name) const;
	const TruthLog& truth() const { return log_; }
	const LabOptions& options() const { return o_; }
	const sim::SimBase& simBase() const { return base_; }
	/** The object shapes, model name → definition. */
	const std::map<std::string, world::ObjectShape>& shapes() const { return shapes_; }
	/** Records a rendered frame's truth (called by the lab's head). */
	void logFrame(uint64_t frame);

 private:
	class LabBase;
	/** The rendering head (LabHead.cpp). */
	std::unique_ptr<hw::HeadDevice> makeHead();
	void afterStep();
	void release(const std::string& name);

	LabOptions o_;
	Eigen::Isometry3d T_C0inA_true_mm_;
	SimBase base_;
	std::map<std::string, Eigen::Isometry3d> poses_;
	std::map<std::string, world::ObjectShape> shapes_;
	TruthLog log_;
	std::unique_ptr<hw::BaseDevice> base_device_;
	std::unique_ptr<hw::HeadDevice> head_;
	std::unique_ptr<GripperPhysics> gripper_;
	std::unique_ptr<SimArm> arm_;
	std::set<std::string> on_board_;
	Eigen::Isometry3d T_C0inW_last_;  ///< C0 when the on-board objects were last moved
};

}  // namespace mrolr::sim
