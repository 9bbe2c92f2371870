#include <mrolr/geometry/Frames.h>
#include <mrolr/sim/SimArm.h>
#include <mrolr/util/Config.h>

#include <ostream>
#include <stdexcept>

namespace mrolr::sim
{
namespace
{
const char* kJointNames[7] = {"d1_mm", "q1_deg", "q2_deg", "q3_deg", "q4_deg", "q5_deg", "q6_deg"};
}

void SimArmOptions::loadFromConfigFile(const mrpt::config::CConfigFileBase& cfg,
                                       const std::string& section)
{
	const bool given = util::hasKey(cfg, section, "joint_min") || util::hasKey(cfg, section, "joint_max");
	const auto lo = given ? util::readDoubles(cfg, section, "joint_min", 7)
	                      : std::vector<double>(min.begin(), min.end());
	const auto hi = given ? util::readDoubles(cfg, section, "joint_max", 7)
	                      : std::vector<double>(max.begin(), max.end());
	for (int i = 0; i < 7; ++i)
	{
		min[i] = lo[i], max[i] = hi[i];
		if (lo[i] >= hi[i])
			throw util::ConfigError(util::describeKey(cfg, section, "joint_max") + ": " +
			                        kJointNames[i] + " maximum must exceed its minimum");
	}
	grasp_radius_m = util::readDouble(cfg, section, "grasp_radius_m", grasp_radius_m);
	open_width_mm = util::readDouble(cfg, section, "open_width_mm", open_width_mm);
	util::requireInRange(cfg, section, "open_width_mm", open_width_mm, 1, 1000);
}

void SimArmOptions::dump(std::ostream& out) const
{
	out << "joint_min =";
	for (double v : min) out << " " << v;
	out << "\njoint_max =";
	for (double v : max) out << " " << v;
	out << "\ngrasp_radius_m = " << grasp_radius_m << "\nopen_width_mm = " << open_width_mm << "\n";
}

SimArm::SimArm(std::function<Eigen::Isometry3d(const hw::ArmJoints&)> T_GinW,
               const SimArmOptions& o, std::map<std::string, Eigen::Isometry3d>& objects,
               mrpt::opengl::COpenGLScene* scene, JawWidth jaw_width)
    : T_GinW_(std::move(T_GinW)),
      options_(o),
      objects_(objects),
      scene_(scene),
      jaw_width_(std::move(jaw_width))
{
	for (int i = 0; i < 7; ++i) joints_[i] = std::clamp(0.0, o.min[i], o.max[i]);
}

void SimArm::moveTo(const hw::ArmJoints& joints)
{
	for (int i = 0; i < 7; ++i)
		if (joints[i] < options_.min[i] || joints[i] > options_.max[i])
			throw std::out_of_range(std::string("arm joint ") + kJointNames[i] + " = " +
			                        std::to_string(joints[i]) + " outside [" +
			                        std::to_string(options_.min[i]) + ", " +
			                        std::to_string(options_.max[i]) + "]");
	joints_ = joints;
	carry();
}

void SimArm::setGripper(bool closed)
{
	closed_ = closed;
	grasped_.clear();
	if (!closed) return;
	const Eigen::Isometry3d T_GinW = T_GinW_(joints_);
	double nearest = options_.grasp_radius_m;
	for (const auto& [name, T_OinW] : objects_)
	{
		const double d = (T_OinW.translation() - T_GinW.translation()).norm();
		const Eigen::Isometry3d T_OinG = T_GinW.inverse() * T_OinW;
		if (d >= nearest || (jaw_width_ && jaw_width_(name, T_OinG) <= 0)) continue;
		nearest = d, grasped_ = name, T_OinG_ = T_OinG;
	}
}

double SimArm::gripperWidthMm() const
{
	if (!closed_) return options_.open_width_mm;
	if (grasped_.empty() || !jaw_width_) return 0;
	return jaw_width_(grasped_, T_OinG_);
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
