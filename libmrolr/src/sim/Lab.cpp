// The simulated lab: devices for the robot, truth for eval.
#include <mrolr/arm/RtxKinematics.h>
#include <mrolr/geometry/Frames.h>
#include <mrolr/sim/Lab.h>
#include <mrolr/sim/Placement.h>
#include <mrolr/sim/SceneBuilder.h>

namespace mrolr::sim
{
namespace
{
Eigen::Isometry3d metres(Eigen::Isometry3d T_mm)
{
	T_mm.translation() /= 1000.0;
	return T_mm;
}

Eigen::Vector3d startPose(const world::World& w)
{
	const auto& s = w.waypoints.front();
	return {s.z_m, s.x_m, s.phi_rad};
}
}  // namespace

std::map<std::string, Eigen::Isometry3d> placedObjectPoses(const world::World& w)
{
	std::map<std::string, Eigen::Isometry3d> out;
	for (const auto& p : w.objects) out[p.name] = T_OinW(w, p);
	return out;
}

/** The base: every step moves the truth, then the arm (mounted on it) and what it holds. */
class Lab::LabBase : public hw::BaseDevice
{
 public:
	explicit LabBase(Lab& lab) : lab_(lab) {}
	void step(const base::WheelControl& u) override
	{
		lab_.base_.step(u);
		lab_.afterStep();
	}
	hw::Odometry odometry() const override { return lab_.base_.odometry(); }

 private:
	Lab& lab_;
};

Lab::Lab(const LabOptions& o)
    : o_(o),
      base_(base::LabmateModel(o.labmate), o.base, startPose(o.world)),
      poses_(placedObjectPoses(o.world)),
      shapes_(loadObjectShapes(o.world))
{
	// The base meets the walls, tables and obstacles of its world (the world must leave it room).
	if (o.world.has_room)
		base_.setCollisionWorld(std::make_shared<CollisionWorld>(o.world, o.base.footprint));
	base_device_ = std::make_unique<LabBase>(*this);
	head_ = makeHead();
	const arm::RtxKinematics kin(o.rtx);
	const Eigen::Isometry3d T_AinC0 = metres(o.mount.T_C0inA.inverse());
	auto T_GinW = [this, kin, T_AinC0](const hw::ArmJoints& j)
	{ return trueC0() * T_AinC0 * metres(kin.T06(arm::RtxJoints::fromMmDeg(j))); };
	const JawGeometry jaws{o.gripper.gripper_opening_max_mm, o.gripper.finger_length_mm,
	                       o.gripper.finger_width_mm};
	std::map<std::string, std::string> model_of;
	for (const auto& p : o.world.objects) model_of[p.name] = p.model;
	gripper_ = std::make_unique<GripperPhysics>(o_.world, shapes_, model_of, jaws, o.gripper_physics,
	                                            poses_);
	arm_ = std::make_unique<SimArm>(T_GinW, o.arm, poses_, nullptr, gripper_.get());
	log_.steps.push_back({0, base_.truePose()});
}

Lab::~Lab() = default;

hw::BaseDevice& Lab::base()
{
	return *base_device_;
}

hw::HeadDevice& Lab::head()
{
	return *head_;
}

hw::ArmDevice& Lab::arm()
{
	return *arm_;
}

Eigen::Isometry3d Lab::trueC0() const
{
	return geometry::T_C0inW(base_.truePose(), o_.bisight.head_height_m);
}

std::string Lab::modelOf(const std::string& name) const
{
	for (const auto& p : o_.world.objects)
		if (p.name == name) return p.model;
	return "";
}

void Lab::afterStep()
{
	arm_->baseMoved();
	log_.steps.push_back({base_.odometry().time_s, base_.truePose()});
}

void Lab::logFrame(uint64_t frame)
{
	log_.frames.push_back({frame, trueC0(), poses_});
}

}  // namespace mrolr::sim
