// The simulated lab behind the mission's devices (sim or served on pseudo-terminals).
#include <mrolr/arm/RtxKinematics.h>
#include <mrolr/geometry/Frames.h>
#include <mrolr/mission/ObjectSearch.h>
#include <mrolr/mission/SimulatedLab.h>
#include <mrolr/sim/SceneBuilder.h>
#include <mrolr/sim/StereoRenderer.h>

namespace mrolr::mission
{
namespace
{
Eigen::Isometry3d metres(Eigen::Isometry3d T_mm)
{
	T_mm.translation() /= 1000.0;
	return T_mm;
}

Eigen::Vector3d startPose(const MissionOptions& o)
{
	if (o.route.empty()) return Eigen::Vector3d::Zero();
	const auto* w = o.world.findWaypoint(o.route.front());
	return {w->z_m, w->x_m, w->phi_rad};
}

/** The lab's head: joint limits of the BiSight model, a move takes [search] head_move_time_s,
 * a grab renders the lab with the objects at their current true poses. The renderer (an EGL
 * context) is built at the first grab, so missions that never grab never need one. */
class LabHead : public hw::HeadDevice
{
 public:
	LabHead(const MissionOptions& o, SimulatedLab& lab) : o_(o), lab_(lab), head_(o.bisight) {}
	double moveTo(const geometry::HeadAngles& target) override
	{
		head_.checkJointLimits(target);
		angles_ = target;
		time_s_ += o_.search.head_move_time_s;
		return o_.search.head_move_time_s;
	}
	geometry::HeadAngles angles() const override { return angles_; }
	hw::StereoImages grab() override;

 private:
	const MissionOptions& o_;
	SimulatedLab& lab_;
	geometry::BiSightHead head_;
	geometry::HeadAngles angles_;
	double time_s_ = 0;
	uint64_t frames_ = 0;
	std::unique_ptr<sim::StereoRenderer> renderer_;
	sim::LabScene scene_;
};

hw::StereoImages LabHead::grab()
{
	if (!renderer_)
	{
		scene_ = sim::buildLabScene(o_.world);
		renderer_ = std::make_unique<sim::StereoRenderer>(head_, sim::RenderOptions());
	}
	for (const auto& [name, T] : lab_.objectPoses())
		if (auto gl = scene_.scene->getByName("object." + name))
			gl->setPose(geometry::cameraPoseToMrpt(T));
	const auto frame = renderer_->render(*scene_.scene, lab_.trueC0(), angles_, frames_++);
	return hw::StereoImages{frame.left, frame.right, angles_, time_s_};
}
}  // namespace

SimulatedLab::SimulatedLab(const MissionOptions& o)
    : o_(o), base_(base::LabmateModel(o.labmate), o.sim_base, startPose(o))
{
	for (const auto& [name, placed] : placedObjects(o.world)) poses_[name] = placed.T_OinW;
	head_ = std::make_unique<LabHead>(o, *this);
	const arm::RtxKinematics kin(o.rtx);
	auto T_GinW = [this, kin](const hw::ArmJoints& j)
	{ return T_AinW_ * metres(kin.T06(arm::RtxJoints::fromMmDeg(j))); };
	arm_ = std::make_unique<sim::SimArm>(T_GinW, o.sim_arm, poses_);
}

SimulatedLab::~SimulatedLab() = default;

Eigen::Isometry3d SimulatedLab::trueC0() const
{
	return geometry::T_C0inW(base_.truePose(), o_.bisight.head_height_m);
}

void SimulatedLab::dockArm()
{
	T_AinW_ = trueC0() * metres(o_.dock.T_C0inA.inverse());
}

}  // namespace mrolr::mission
