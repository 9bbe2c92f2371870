#include <mrolr/slam/SlamOptions.h>
#include <mrolr/util/Config.h>

#include <ostream>
#include <stdexcept>

namespace mrolr::slam
{
using util::readDouble;
using util::requireInRange;

UpdateMethod parseUpdateMethod(const std::string& name)
{
	if (name == "sequential") return UpdateMethod::Sequential;
	if (name == "batch") return UpdateMethod::Batch;
	if (name == "postponed") return UpdateMethod::Postponed;
	throw std::invalid_argument("unknown update method '" + name +
	                            "' (expected sequential, batch or postponed)");
}

std::string toString(UpdateMethod m)
{
	switch (m)
	{
		case UpdateMethod::Sequential:
			return "sequential";
		case UpdateMethod::Batch:
			return "batch";
		case UpdateMethod::Postponed:
			return "postponed";
	}
	return "?";
}

JacobianPoint parseJacobianPoint(const std::string& name)
{
	if (name == "standard") return JacobianPoint::Standard;
	if (name == "first_estimate") return JacobianPoint::FirstEstimate;
	throw std::invalid_argument("unknown jacobians '" + name +
	                            "' (expected standard or first_estimate)");
}

std::string toString(JacobianPoint point)
{
	return point == JacobianPoint::FirstEstimate ? "first_estimate" : "standard";
}

namespace
{
JacobianPoint readJacobians(const mrpt::config::CConfigFileBase& cfg, const std::string& s)
{
	if (!util::hasKey(cfg, s, "jacobians")) return JacobianPoint::Standard;
	try
	{
		return parseJacobianPoint(util::readString(cfg, s, "jacobians"));
	}
	catch (const std::invalid_argument& e)
	{
		throw util::ConfigError(util::describeKey(cfg, s, "jacobians") + ": " + e.what());
	}
}

double readIn(const mrpt::config::CConfigFileBase& cfg, const std::string& s,
              const std::string& key, double lo, double hi)
{
	const double v = readDouble(cfg, s, key);
	requireInRange(cfg, s, key, v, lo, hi);
	return v;
}
}  // namespace

void HeadModelOptions::loadFromConfigFile(const mrpt::config::CConfigFileBase& cfg,
                                          const std::string& s)
{
	constants.interocular_m = readIn(cfg, s, "interocular_m", 1e-3, 10);
	constants.head_height_m = readIn(cfg, s, "head_height_m", -10, 10);
	pan_limit_deg = readIn(cfg, s, "pan_limit_deg", 0, 180);
	tilt_limit_deg = readIn(cfg, s, "tilt_limit_deg", 0, 90);
	vergence_limit_deg = readIn(cfg, s, "vergence_limit_deg", 0, 90);
}

void HeadModelOptions::dumpToTextStream(std::ostream& out) const
{
	out << "interocular_m = " << constants.interocular_m
	    << "\nhead_height_m = " << constants.head_height_m << "\npan_limit_deg = " << pan_limit_deg
	    << "\ntilt_limit_deg = " << tilt_limit_deg
	    << "\nvergence_limit_deg = " << vergence_limit_deg << "\n";
}

void SlamOptions::loadFromConfigFile(const mrpt::config::CConfigFileBase& cfg, const std::string& s)
{
	std_pan_rad = readIn(cfg, s, "std_pan_rad", 1e-9, 1);
	std_elevation_rad = readIn(cfg, s, "std_elevation_rad", 1e-9, 1);
	std_vergence_rad = readIn(cfg, s, "std_vergence_rad", 1e-9, 1);
	try
	{
		update_method = parseUpdateMethod(util::readString(cfg, s, "update_method"));
	}
	catch (const std::invalid_argument& e)
	{
		throw util::ConfigError(util::describeKey(cfg, s, "update_method") + ": " + e.what());
	}
	jacobians = readJacobians(cfg, s);
	process_noise_order = static_cast<int>(util::readInt(cfg, s, "process_noise_order", 1));
	requireInRange(cfg, s, "process_noise_order", process_noise_order, 1, 2);
	gate_probability = readIn(cfg, s, "gate_probability", 0.5, 1 - 1e-12);
	process_noise_floor_m = readIn(cfg, s, "process_noise_floor_m", 0, 1);
	process_noise_floor_rad = readIn(cfg, s, "process_noise_floor_rad", 0, 1);
	min_visible_features = static_cast<int>(readIn(cfg, s, "min_visible_features", 0, 100));
	attempt_window = static_cast<int>(readIn(cfg, s, "attempt_window", 1, 1000));
	visibility_ratio_min = readIn(cfg, s, "visibility_ratio_min", 0, 1);
	visibility_ratio_max = readIn(cfg, s, "visibility_ratio_max", 1, 100);
	max_view_change_deg = readIn(cfg, s, "max_view_change_deg", 0, 180);
	innovation_volume_sigma = readIn(cfg, s, "innovation_volume_sigma", 0.1, 10);
	head_speed_deg_per_s = readIn(cfg, s, "head_speed_deg_per_s", 1e-3, 1e4);
	saccade_overhead_s = readIn(cfg, s, "saccade_overhead_s", 0, 100);
	step_time_s = readIn(cfg, s, "step_time_s", 1e-3, 1e4);
}

void SlamOptions::dumpToTextStream(std::ostream& out) const
{
	out << "[slam]\nstd_pan_rad = " << std_pan_rad << "\nstd_elevation_rad = " << std_elevation_rad
	    << "\nstd_vergence_rad = " << std_vergence_rad
	    << "\nupdate_method = " << toString(update_method)
	    << "\njacobians = " << toString(jacobians)
	    << "\nprocess_noise_order = " << process_noise_order
	    << "\ngate_probability = " << gate_probability
	    << "\nprocess_noise_floor_m = " << process_noise_floor_m
	    << "\nprocess_noise_floor_rad = " << process_noise_floor_rad
	    << "\nmin_visible_features = " << min_visible_features
	    << "\nattempt_window = " << attempt_window
	    << "\nvisibility_ratio_min = " << visibility_ratio_min
	    << "\nvisibility_ratio_max = " << visibility_ratio_max
	    << "\nmax_view_change_deg = " << max_view_change_deg
	    << "\ninnovation_volume_sigma = " << innovation_volume_sigma
	    << "\nhead_speed_deg_per_s = " << head_speed_deg_per_s
	    << "\nsaccade_overhead_s = " << saccade_overhead_s << "\nstep_time_s = " << step_time_s
	    << "\n";
	head.dumpToTextStream(out);
}

}  // namespace mrolr::slam
