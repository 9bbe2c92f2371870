#include <mrolr/slam/SlamOptions.h>
#include <mrolr/util/OptionsBinder.h>

#include <ostream>
#include <stdexcept>

namespace mrolr::slam
{
namespace
{
const util::ChoiceNames<UpdateMethod>& updateMethodNames()
{
	static const util::ChoiceNames<UpdateMethod> names = {{"sequential", UpdateMethod::Sequential},
	                                                      {"batch", UpdateMethod::Batch},
	                                                      {"postponed", UpdateMethod::Postponed}};
	return names;
}

const util::ChoiceNames<JacobianPoint>& jacobianNames()
{
	static const util::ChoiceNames<JacobianPoint> names = {
	    {"standard", JacobianPoint::Standard}, {"first_estimate", JacobianPoint::FirstEstimate}};
	return names;
}

}  // namespace

std::string toString(UpdateMethod m)
{
	return util::nameOf(updateMethodNames(), m);
}

std::string toString(JacobianPoint point)
{
	return util::nameOf(jacobianNames(), point);
}

namespace
{
using H = HeadModelOptions;
using S = SlamOptions;
using util::Presence;

const util::OptionsBinder<H>& headBinder()
{
	static const auto b =
	    util::OptionsBinder<H>()
	        .number("interocular_m", [](H& o) -> double& { return o.constants.interocular_m; },
	                1e-3, 10)
	        .number("head_height_m", [](H& o) -> double& { return o.constants.head_height_m; },
	                -10, 10)
	        .number("pan_limit_deg", &H::pan_limit_deg, 0, 180)
	        .number("tilt_limit_deg", &H::tilt_limit_deg, 0, 90)
	        .number("vergence_limit_deg", &H::vergence_limit_deg, 0, 90);
	return b;
}

const util::OptionsBinder<S>& slamBinder()
{
	static const auto b =
	    util::OptionsBinder<S>()
	        .number("std_pan_rad", &S::std_pan_rad, 1e-9, 1)
	        .number("std_elevation_rad", &S::std_elevation_rad, 1e-9, 1)
	        .number("std_vergence_rad", &S::std_vergence_rad, 1e-9, 1)
	        .choice("update_method", &S::update_method, updateMethodNames())
	        // FEJ-EKF and the second-order process noise are variants a user may leave out
	        .choice("jacobians", &S::jacobians, jacobianNames(), Presence::Optional)
	        .integer("process_noise_order", &S::process_noise_order, 1, 2, Presence::Optional)
	        .number("gate_probability", &S::gate_probability, 0.5, 1 - 1e-12)
	        .number("process_noise_floor_m", &S::process_noise_floor_m, 0, 1)
	        .number("process_noise_floor_rad", &S::process_noise_floor_rad, 0, 1)
	        .integer("min_visible_features", &S::min_visible_features, 0, 100)
	        .integer("attempt_window", &S::attempt_window, 1, 1000)
	        .number("visibility_ratio_min", &S::visibility_ratio_min, 0, 1)
	        .number("visibility_ratio_max", &S::visibility_ratio_max, 1, 100)
	        .number("max_view_change_deg", &S::max_view_change_deg, 0, 180)
	        .number("innovation_volume_sigma", &S::innovation_volume_sigma, 0.1, 10)
	        .number("head_speed_deg_per_s", &S::head_speed_deg_per_s, 1e-3, 1e4)
	        .number("saccade_overhead_s", &S::saccade_overhead_s, 0, 100)
	        .number("step_time_s", &S::step_time_s, 1e-3, 1e4);
	return b;
}
}  // namespace

void HeadModelOptions::loadFromConfigFile(const mrpt::config::CConfigFileBase& cfg,
                                          const std::string& s)
{
	headBinder().load(cfg, s, *this);
}

void HeadModelOptions::dumpToTextStream(std::ostream& out) const
{
	headBinder().dump(out, *this);
}

void SlamOptions::loadFromConfigFile(const mrpt::config::CConfigFileBase& cfg, const std::string& s)
{
	slamBinder().load(cfg, s, *this);
}

void SlamOptions::dumpToTextStream(std::ostream& out) const
{
	out << "[slam]\n";
	slamBinder().dump(out, *this);
	head.dumpToTextStream(out);
}

}  // namespace mrolr::slam
