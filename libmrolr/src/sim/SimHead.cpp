#include <mrolr/sim/SimHead.h>
#include <mrolr/util/OptionsBinder.h>

#include <algorithm>
#include <cmath>
#include <ostream>

namespace mrolr::sim
{
namespace
{
using O = SimHeadOptions;
constexpr auto kOpt = util::Presence::Optional;

const util::OptionsBinder<O>& simHeadOptionsBinder()
{
	static const auto b = util::OptionsBinder<O>()
	    .number("pan_speed_dps", &O::pan_speed_dps, 1e-3, 1e4, kOpt)
	    .number("tilt_speed_dps", &O::tilt_speed_dps, 1e-3, 1e4, kOpt)
	    .number("vergence_speed_dps", &O::vergence_speed_dps, 1e-3, 1e4, kOpt)
	    .number("settle_s", &O::settle_s, 0, 10, kOpt);
	return b;
}
}  // namespace

void SimHeadOptions::loadFromConfigFile(const mrpt::config::CConfigFileBase& cfg,
                                        const std::string& section)
{
	simHeadOptionsBinder().load(cfg, section, *this);
}

void SimHeadOptions::dump(std::ostream& out) const
{
	simHeadOptionsBinder().dump(out, *this);
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
