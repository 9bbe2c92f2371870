#include <mrolr/geometry/Frames.h>
#include <mrolr/sim/SimArm.h>
#include <mrolr/util/OptionsBinder.h>

#include <algorithm>
#include <cmath>
#include <ostream>
#include <stdexcept>

namespace mrolr::sim
{
namespace
{
const char* kJointNames[7] = {"d1_mm", "q1_deg", "q2_deg", "q3_deg", "q4_deg", "q5_deg", "q6_deg"};
}

namespace
{
using A = SimArmOptions;
constexpr auto kOpt = util::Presence::Optional;  // the simulator's defaults: the thesis's arm

const util::OptionsBinder<A>& simArmBinder()
{
	static const auto b = util::OptionsBinder<A>()
	                          .numbers("joint_min", &A::min, 7, -1e6, 1e6, kOpt)
	                          .numbers("joint_max", &A::max, 7, -1e6, 1e6, kOpt)
	                          .number("open_width_mm", &A::open_width_mm, 1, 1000, kOpt)
	                          .number("mount_error_mm", &A::mount_error_mm, 0, 200, kOpt)
	                          .number("mount_error_deg", &A::mount_error_deg, 0, 20, kOpt)
	                          .flag("draw_arm", &A::drawn, kOpt);
	return b;
}
}  // namespace

void SimArmOptions::loadFromConfigFile(const mrpt::config::CConfigFileBase& cfg,
                                       const std::string& section)
{
	if (util::hasKey(cfg, section, "grasp_radius_m"))
		throw util::ConfigError(util::describeKey(cfg, section, "grasp_radius_m") +
		                        ": removed; the gripper now holds only what its jaws straddle and "
		                        "fit ([sim_gripper], docs/sim.md)");
	for (const auto& [key, other] : {std::pair{"joint_min", "joint_max"}, {"joint_max", "joint_min"}})
		if (util::hasKey(cfg, section, key) && !util::hasKey(cfg, section, other))
			throw util::ConfigError(util::describeKey(cfg, section, other) + ": missing (" +
			                        key + " and " + other + " come together)");
	simArmBinder().load(cfg, section, *this);
	for (int i = 0; i < 7; ++i)
		if (min[i] >= max[i])
			throw util::ConfigError(util::describeKey(cfg, section, "joint_max") + ": " +
			                        kJointNames[i] + " maximum must exceed its minimum");
}

void SimArmOptions::dump(std::ostream& out) const
{
	simArmBinder().dump(out, *this);
}

SimArm::SimArm(std::function<Eigen::Isometry3d(const hw::ArmJoints&)> T_GinW,
               const SimArmOptions& o, std::map<std::string, Eigen::Isometry3d>& objects,
               mrpt::opengl::COpenGLScene* scene, GripperPhysics* physics)
    : T_GinW_(std::move(T_GinW)),
      options_(o),
      objects_(objects),
      scene_(scene),
      physics_(physics)
{
	// parked as B.3.1 starts it: the column at the top, the arm straight, above what it serves
	joints_[0] = o.max[0];
	for (int i = 1; i < 7; ++i) joints_[i] = std::clamp(0.0, o.min[i], o.max[i]);
}

void SimArm::dock(bool docked)
{
	if (!docked && !grasped_.empty())
		throw std::logic_error("the arm holds '" + grasped_ +
		                       "': its platform is not de-coupled with an object in the jaws");
	docked_ = docked;
}

void SimArm::requireDocked(const char* what) const
{
	if (!docked_)
		throw std::logic_error(std::string("the arm's platform is not docked with the base: it "
		                                   "does not ") + what);
}

void SimArm::moveTo(const hw::ArmJoints& joints)
{
	requireDocked("move");
	for (int i = 0; i < 7; ++i)
		if (joints[i] < options_.min[i] || joints[i] > options_.max[i])
			throw std::out_of_range(std::string("arm joint ") + kJointNames[i] + " = " +
			                        std::to_string(joints[i]) + " outside [" +
			                        std::to_string(options_.min[i]) + ", " +
			                        std::to_string(options_.max[i]) + "]");
	const int n = motionSteps(joints);
	const hw::ArmJoints from = joints_;
	for (int k = 1; k <= n; ++k)
	{
		hw::ArmJoints j;
		for (int i = 0; i < 7; ++i) j[i] = from[i] + (joints[i] - from[i]) * k / n;
		const Eigen::Isometry3d T_before = T_GinW_(joints_), T_now = T_GinW_(j);
		if (physics_)
			if (const auto table = physics_->step(T_before, T_now, separationMm(), grasped_))
				throw hw::ArmBlocked("the gripper met table '" + *table + "' after " +
				                     std::to_string(k - 1) + " of " + std::to_string(n) +
				                     " steps of the move; the arm stopped there");
		joints_ = j;
		carry();
	}
}

int SimArm::motionSteps(const hw::ArmJoints& joints) const
{
	if (!physics_) return 1;
	const Eigen::Isometry3d a = T_GinW_(joints_), b = T_GinW_(joints);
	// a rotation moves the fingertips about 0.3 m from the wrist's axes at most
	const double travel_mm = 1000.0 * ((b.translation() - a.translation()).norm() +
	                                   0.3 * Eigen::AngleAxisd(a.linear().transpose() * b.linear()).angle());
	double joint_travel = 0;  // the middle of a joint move can swing wide of both ends
	for (int i = 1; i < 7; ++i) joint_travel = std::max(joint_travel, std::abs(joints[i] - joints_[i]));
	const double swing_mm = joint_travel * M_PI / 180.0 * 700.0;
	const double step = physics_->options().motion_step_mm;
	return std::clamp(static_cast<int>(std::ceil(std::max(travel_mm, swing_mm) / step)), 1, 4000);
}

double SimArm::separationMm() const
{
	if (!closed_) return physics_ ? physics_->jaws().opening_mm : options_.open_width_mm;
	return grasped_.empty() ? 0.0 : width_mm_;
}

void SimArm::setGripper(bool closed)
{
	requireDocked("grip");
	if (!closed && !grasped_.empty() && on_release_) on_release_(grasped_);
	closed_ = closed;
	grasped_.clear();
	width_mm_ = 0;
	if (!closed || !physics_) return;
	const auto grip = physics_->close(T_GinW_(joints_));
	grasped_ = grip.object, width_mm_ = grip.width_mm, T_OinG_ = grip.T_OinG;
}

double SimArm::gripperWidthMm() const
{
	if (!closed_) return options_.open_width_mm;
	return grasped_.empty() ? 0.0 : width_mm_;
}

void SimArm::carry()
{
	if (grasped_.empty()) return;
	const Eigen::Isometry3d T_OinW = T_GinW_(joints_) * T_OinG_;
	objects_[grasped_] = T_OinW;
	if (!scene_) return;
	if (auto obj = scene_->getByName("object." + grasped_))
		obj->setPose(geometry::cameraPoseToMrpt(T_OinW));
}

}  // namespace mrolr::sim
