#include <mrolr/sim/SimHead.h>
#include <mrolr/util/Config.h>

#include <algorithm>
#include <cmath>
#include <ostream>

namespace mrolr::sim
{
void SimHeadOptions::loadFromConfigFile(const mrpt::config::CConfigFileBase& cfg,
                                        const std::string& section)
{
	using namespace util;
	pan_speed_dps = readDouble(cfg, section, "pan_speed_dps", pan_speed_dps);
	tilt_speed_dps = readDouble(cfg, section, "tilt_speed_dps", tilt_speed_dps);
	vergence_speed_dps = readDouble(cfg, section, "vergence_speed_dps", vergence_speed_dps);
	settle_s = readDouble(cfg, section, "settle_s", settle_s);
	requireInRange(cfg, section, "pan_speed_dps", pan_speed_dps, 1e-3, 1e4);
	requireInRange(cfg, section, "tilt_speed_dps", tilt_speed_dps, 1e-3, 1e4);
	requireInRange(cfg, section, "vergence_speed_dps", vergence_speed_dps, 1e-3, 1e4);
	requireInRange(cfg, section, "settle_s", settle_s, 0, 10);
}

void SimHeadOptions::dump(std::ostream& out) const
{
	out << "pan_speed_dps = " << pan_speed_dps << "\ntilt_speed_dps = " << tilt_speed_dps
	    << "\nvergence_speed_dps = " << vergence_speed_dps << "\nsettle_s = " << settle_s << "\n";
}

SimHead::SimHead(StereoRenderer& renderer, const mrpt::opengl::COpenGLScene& scene,
                 std::function<Eigen::Isometry3d()> T_C0inW, const SimHeadOptions& options)
    : renderer_(renderer), scene_(scene), T_C0inW_(std::move(T_C0inW)), options_(options)
{
}

double SimHead::moveTo(const geometry::HeadAngles& target)
{
	renderer_.head().checkJointLimits(target);
	const double k = 180 / M_PI;
	const double t =
	    std::max(
	        {std::abs(target.pan - angles_.pan) * k / options_.pan_speed_dps,
	         std::abs(target.tilt - angles_.tilt) * k / options_.tilt_speed_dps,
	         std::abs(target.verg_left - angles_.verg_left) * k / options_.vergence_speed_dps,
	         std::abs(target.verg_right - angles_.verg_right) * k / options_.vergence_speed_dps}) +
	    options_.settle_s;
	angles_ = target;
	time_s_ += t;
	return t;
}

hw::StereoImages SimHead::grab()
{
	last_ = renderer_.render(scene_, T_C0inW_(), angles_, frames_++);
	return hw::StereoImages{last_.left, last_.right, angles_, time_s_};
}

}  // namespace mrolr::sim
