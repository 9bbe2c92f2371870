// The simulated lab: devices for the robot, truth for eval.
#include <mrolr/arm/RtxKinematics.h>
#include <mrolr/geometry/Frames.h>
#include <mrolr/geometry/PoseUnits.h>
#include <mrolr/sim/Lab.h>
#include <mrolr/sim/Placement.h>
#include <mrolr/sim/SceneBuilder.h>

#include <random>

namespace mrolr::sim
{
namespace
{
/** The nominal mount off by one draw of the dock's error (SimArmOptions::mount_error_*). */
Eigen::Isometry3d dockedMount(const LabOptions& o)
{
	std::mt19937 rng(o.seed * 7919u + 17u);
	std::uniform_real_distribution<double> u(-1.0, 1.0);
	Eigen::Vector3d t, r;
	for (int i = 0; i < 3; ++i) t[i] = o.arm.mount_error_mm * u(rng);
	for (int i = 0; i < 3; ++i) r[i] = o.arm.mount_error_deg * M_PI / 180.0 * u(rng);
	const Eigen::Matrix3d R = (Eigen::AngleAxisd(r[2], Eigen::Vector3d::UnitZ()) *
	                           Eigen::AngleAxisd(r[1], Eigen::Vector3d::UnitY()) *
	                           Eigen::AngleAxisd(r[0], Eigen::Vector3d::UnitX()))
	                              .toRotationMatrix();
	Eigen::Isometry3d D = Eigen::Isometry3d::Identity();
	D.linear() = R, D.translation() = t;
	return D * o.mount.T_C0inA;
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
      T_C0inA_true_mm_(dockedMount(o)),
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
	auto T_GinW = [this, kin](const hw::ArmJoints& j)
	{ return T_AinW() * geometry::inMetres(kin.T06(arm::RtxJoints::fromMmDeg(j))); };
	const JawGeometry jaws{o.gripper.gripper_opening_max_mm, o.gripper.finger_length_mm,
	                       o.gripper.finger_width_mm};
	std::map<std::string, std::string> model_of;
	for (const auto& p : o.world.objects) model_of[p.name] = p.model;
	gripper_ = std::make_unique<GripperPhysics>(o_.world, shapes_, model_of, jaws, o.gripper_physics,
	                                            poses_);
	arm_ = std::make_unique<SimArm>(T_GinW, o.arm, poses_, nullptr, gripper_.get());
	arm_->onRelease([this](const std::string& name) { release(name); });
	T_C0inW_last_ = trueC0();
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

Eigen::Isometry3d Lab::T_AinW() const
{
	return trueC0() * geometry::inMetres(T_C0inA_true_mm_.inverse());
}

std::string Lab::modelOf(const std::string& name) const
{
	for (const auto& p : o_.world.objects)
		if (p.name == name) return p.model;
	return "";
}

DeckSupport Lab::deck() const
{
	// the deck covers the base's physical footprint (centred offset_m ahead of the axle)
	const auto& f = o_.base.footprint;
	DeckSupport d;
	d.T_TopInW = trueC0() * Eigen::Translation3d(
	                            0, o_.labmate.deck_height_m - o_.bisight.head_height_m, f.offset_m);
	d.half_x_m = f.width_m / 2, d.half_z_m = f.length_m / 2;
	return d;
}

void Lab::release(const std::string& name)
{
	if (gripper_->release(name, deck())) on_board_.insert(name);
}

void Lab::afterStep()
{
	const Eigen::Isometry3d T_C0inW = trueC0();  // what rides on the deck moves with the base
	for (const auto& name : on_board_)
		poses_.at(name) = T_C0inW * T_C0inW_last_.inverse() * poses_.at(name);
	T_C0inW_last_ = T_C0inW;
	arm_->baseMoved();
	log_.steps.push_back({base_.odometry().time_s, base_.truePose()});
}

void Lab::logFrame(uint64_t frame)
{
	log_.frames.push_back({frame, trueC0(), poses_});
}

}  // namespace mrolr::sim
