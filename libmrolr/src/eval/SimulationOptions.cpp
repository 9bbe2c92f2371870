#include <mrolr/eval/EkfSimulation.h>
#include <mrolr/util/OptionsBinder.h>

#include <filesystem>
#include <ostream>

namespace mrolr::eval
{
namespace
{
using S = SimulationOptions;

const util::OptionsBinder<S>& binder()
{
	static const auto b =
	    util::OptionsBinder<S>()
	        .integer("seed", &S::seed, 0, 4000000000000000000L)
	        .number("true_velocity_noise_fraction", &S::true_velocity_noise_fraction, 0, 1)
	        .number("true_std_pan_rad", &S::true_std_pan_rad, 0, 1)
	        .number("true_std_elevation_rad", &S::true_std_elevation_rad, 0, 1)
	        .number("true_std_vergence_rad", &S::true_std_vergence_rad, 0, 1)
	        .number("slip_burst_probability", &S::slip_burst_probability, 0, 1)
	        .integer("slip_burst_length_steps", &S::slip_burst_length_steps, 1, 1000)
	        .number("slip_fraction", &S::slip_fraction, 0, 1)
	        .number("outlier_fraction", &S::outlier_fraction, 0, 1)
	        .number("outlier_magnitude_rad", &S::outlier_magnitude_rad, 0, 3)
	        .integer("measurements_per_step", &S::measurements_per_step, 0, 100)
	        .number("max_range_m", &S::max_range_m, 0.1, 1000)
	        .number("search_pan_deg", &S::search_pan_deg, 0, 180)
	        .number("search_window_deg", &S::search_window_deg, 1, 180)
	        .integer("laps", &S::laps, 1, 1000);
	return b;
}
}  // namespace

void SimulationOptions::loadFromConfigFile(const mrpt::config::CConfigFileBase& cfg,
                                           const std::string& s)
{
	binder().load(cfg, s, *this);
}

void SimulationOptions::dumpToTextStream(std::ostream& out) const
{
	out << "[simulation]\n";
	binder().dump(out, *this);
}

SimulationSetup SimulationSetup::load(const std::string& path)
{
	namespace fs = std::filesystem;
	const auto cfg = util::openConfigFile(path, "--config");
	SimulationSetup s;
	s.sim.loadFromConfigFile(cfg, "simulation");
	s.slam.loadFromConfigFile(cfg, "slam");
	const fs::path dir = fs::path(path).parent_path();
	const auto relative = [&](const std::string& key)
	{ return (dir / util::readString(cfg, "simulation", key)).string(); };
	const auto labmate = util::openConfigFile(relative("labmate_config_file"),
	                             util::describeKey(cfg, "simulation", "labmate_config_file"));
	s.labmate.loadFromConfigFile(labmate, "labmate");
	s.trajectory.loadFromConfigFile(labmate, "trajectory");
	const auto head = util::openConfigFile(relative("bisight_config_file"),
	                          util::describeKey(cfg, "simulation", "bisight_config_file"));
	s.slam.head.loadFromConfigFile(head, "bisight");
	return s;
}

}  // namespace mrolr::eval
