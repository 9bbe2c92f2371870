// The simulated lab's head: joint limits of the BiSight model and rendered stereo pairs.
#include <mrolr/geometry/Frames.h>
#include <mrolr/sim/ArmVisual.h>
#include <mrolr/sim/Lab.h>
#include <mrolr/sim/SceneBuilder.h>

namespace mrolr::sim
{
namespace
{
/** Moves take head_move_time_s; a grab renders the lab with the objects at their current true
 * poses and logs the frame's truth. The renderer (an EGL context) is built at the first grab, so
 * runs that never grab never need one. */
class LabHead : public hw::HeadDevice
{
 public:
	LabHead(Lab& lab) : lab_(lab), head_(lab.options().bisight) {}
	double moveTo(const geometry::HeadAngles& target) override
	{
		head_.checkJointLimits(target);
		angles_ = target;
		time_s_ += lab_.options().head_move_time_s;
		return lab_.options().head_move_time_s;
	}
	geometry::HeadAngles angles() const override { return angles_; }
	hw::StereoImages grab() override;

 private:
	Lab& lab_;
	geometry::BiSightHead head_;
	geometry::HeadAngles angles_;
	double time_s_ = 0;
	uint64_t frames_ = 0;
	std::unique_ptr<StereoRenderer> renderer_;
	std::unique_ptr<ArmVisual> arm_visual_;
	LabScene scene_;
};

hw::StereoImages LabHead::grab()
{
	if (!renderer_)
	{
		scene_ = buildLabScene(lab_.options().world, lab_.shapes());
		renderer_ = std::make_unique<StereoRenderer>(head_, lab_.options().render);
		const auto& o = lab_.options();
		if (o.arm.drawn)
		{
			arm_visual_ = std::make_unique<ArmVisual>(o.rtx, o.gripper,
			                                          o.gripper_physics.finger_thickness_mm, o.marker);
			scene_.scene->insert(arm_visual_->object());
		}
	}
	if (arm_visual_) arm_visual_->object()->setVisibility(lab_.simArm().docked());
	if (arm_visual_ && lab_.simArm().docked())
		arm_visual_->update(lab_.T_AinW(), arm::RtxJoints::fromMmDeg(lab_.simArm().joints()),
		                    lab_.simArm().separationMm());
	for (const auto& [name, T] : lab_.objectPoses())
		if (auto gl = scene_.scene->getByName("object." + name))
			gl->setPose(geometry::cameraPoseToMrpt(T));
	const uint64_t frame = frames_++;
	const auto f = renderer_->render(*scene_.scene, lab_.trueC0(), angles_, frame);
	lab_.logFrame(frame);
	return hw::StereoImages{f.left, f.right, angles_, time_s_, frame};
}
}  // namespace

std::unique_ptr<hw::HeadDevice> Lab::makeHead()
{
	return std::make_unique<LabHead>(*this);
}

}  // namespace mrolr::sim
