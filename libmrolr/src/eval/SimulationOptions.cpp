#include <mrolr/eval/EkfSimulation.h>
#include <mrolr/util/Config.h>

#include <mrpt/config/CConfigFile.h>

#include <filesystem>
#include <fstream>
#include <ostream>

namespace mrolr::eval
{
namespace
{
double readIn(const mrpt::config::CConfigFileBase& cfg, const std::string& s,
              const std::string& key, double lo, double hi)
{
	const double v = util::readDouble(cfg, s, key);
	util::requireInRange(cfg, s, key, v, lo, hi);
	return v;
}

/** Opens an .ini that must exist (CConfigFile silently reads a missing file as empty). */
mrpt::config::CConfigFile openIni(const std::string& path, const std::string& named_by)
{
	if (!std::ifstream(path).good())
		throw util::ConfigError("cannot read '" + path + "' (named by " + named_by + ")");
	return mrpt::config::CConfigFile(path);
}
}  // namespace

void SimulationOptions::loadFromConfigFile(const mrpt::config::CConfigFileBase& cfg,
                                           const std::string& s)
{
	seed = static_cast<uint64_t>(readIn(cfg, s, "seed", 0, 4e18));
	true_velocity_noise_fraction = readIn(cfg, s, "true_velocity_noise_fraction", 0, 1);
	true_std_pan_rad = readIn(cfg, s, "true_std_pan_rad", 0, 1);
	true_std_elevation_rad = readIn(cfg, s, "true_std_elevation_rad", 0, 1);
	true_std_vergence_rad = readIn(cfg, s, "true_std_vergence_rad", 0, 1);
	slip_burst_probability = readIn(cfg, s, "slip_burst_probability", 0, 1);
	slip_burst_length_steps = static_cast<int>(readIn(cfg, s, "slip_burst_length_steps", 1, 1000));
	slip_fraction = readIn(cfg, s, "slip_fraction", 0, 1);
	outlier_fraction = readIn(cfg, s, "outlier_fraction", 0, 1);
	outlier_magnitude_rad = readIn(cfg, s, "outlier_magnitude_rad", 0, 3);
	measurements_per_step = static_cast<int>(readIn(cfg, s, "measurements_per_step", 0, 100));
	max_range_m = readIn(cfg, s, "max_range_m", 0.1, 1000);
	search_pan_deg = readIn(cfg, s, "search_pan_deg", 0, 180);
	search_window_deg = readIn(cfg, s, "search_window_deg", 1, 180);
	laps = static_cast<int>(readIn(cfg, s, "laps", 1, 1000));
}

void SimulationOptions::dumpToTextStream(std::ostream& out) const
{
	out << "[simulation]\nseed = " << seed
	    << "\ntrue_velocity_noise_fraction = " << true_velocity_noise_fraction
	    << "\ntrue_std_pan_rad = " << true_std_pan_rad
	    << "\ntrue_std_elevation_rad = " << true_std_elevation_rad
	    << "\ntrue_std_vergence_rad = " << true_std_vergence_rad
	    << "\nslip_burst_probability = " << slip_burst_probability
	    << "\nslip_burst_length_steps = " << slip_burst_length_steps
	    << "\nslip_fraction = " << slip_fraction << "\noutlier_fraction = " << outlier_fraction
	    << "\noutlier_magnitude_rad = " << outlier_magnitude_rad
	    << "\nmeasurements_per_step = " << measurements_per_step
	    << "\nmax_range_m = " << max_range_m << "\nsearch_pan_deg = " << search_pan_deg
	    << "\nsearch_window_deg = " << search_window_deg << "\nlaps = " << laps << "\n";
}

SimulationSetup SimulationSetup::load(const std::string& path)
{
	namespace fs = std::filesystem;
	const auto cfg = openIni(path, "--config");
	SimulationSetup s;
	s.sim.loadFromConfigFile(cfg, "simulation");
	s.slam.loadFromConfigFile(cfg, "slam");
	const fs::path dir = fs::path(path).parent_path();
	const auto relative = [&](const std::string& key)
	{ return (dir / util::readString(cfg, "simulation", key)).string(); };
	const auto labmate = openIni(relative("labmate_config_file"),
	                             util::describeKey(cfg, "simulation", "labmate_config_file"));
	s.labmate.loadFromConfigFile(labmate, "labmate");
	s.trajectory.loadFromConfigFile(labmate, "trajectory");
	const auto head = openIni(relative("bisight_config_file"),
	                          util::describeKey(cfg, "simulation", "bisight_config_file"));
	s.slam.head.loadFromConfigFile(head, "bisight");
	return s;
}

}  // namespace mrolr::eval
