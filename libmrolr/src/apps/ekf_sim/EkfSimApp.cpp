#include "SimulationOutputs.h"

#include <mrolr/apps/EkfSimApp.h>
#include <mrolr/apps/TclapSupport.h>
#include <mrolr/util/Cli.h>

#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <ostream>

namespace mrolr::apps
{
std::string EkfSimApp::defaultConfigPath()
{
	return util::projectFile("config/ekf_sim.ini");
}

void EkfSimApp::initialize(const std::vector<std::string>& args)
{
	TCLAP::CmdLine cmd(
	    "mrolr-ekf-sim: Monte-Carlo runs of the active-vision EKF-SLAM simulator (thesis 5.4-5.9)",
	    ' ', "1");
	TCLAP::ValueArg<std::string> world("", "world", "world file (maps/<name>/world.ini)", true, "",
	                                   "FILE", cmd);
	TCLAP::ValueArg<std::string> cfg("", "config", "simulator .ini (default config/ekf_sim.ini)",
	                                 false, "", "FILE", cmd);
	TCLAP::ValueArg<std::string> nruns("", "runs", "number of Monte-Carlo runs (default 1)", false,
	                                   "1", "N", cmd);
	TCLAP::ValueArg<std::string> s("", "seed", "seed of run 0 (default: [simulation] seed)", false,
	                               "", "S", cmd);
	TCLAP::ValueArg<std::string> out(
	    "", "out",
	    "write steps.csv, nees.csv, paths.png and run 0's truth.tum, estimate.tum, odometry.tum here",
	    false, "", "DIR", cmd);
	TCLAP::ValueArg<std::string> rawlog("", "rawlog", "write run 0 as an MRPT rawlog", false, "",
	                                    "FILE", cmd);
	TCLAP::SwitchArg js("", "json", "print one JSON object", cmd);
	TCLAP::SwitchArg quiet("", "quiet", "no progress line", cmd);
	if (!parseTclap(cmd, args))
	{
		help_shown = true;
		return;
	}
	world_path = world.getValue();
	config_path = cfg.getValue().empty() ? defaultConfigPath() : cfg.getValue();
	const double n = util::parseNumberArg(nruns.getValue(), "--runs");
	if (!(n >= 1 && n <= 100000 && n == std::floor(n)))
		throw util::UsageError("--runs: '" + nruns.getValue() +
		                       "' is not a whole number in 1..100000");
	runs = static_cast<int>(n);
	if (!s.getValue().empty())
	{
		const double v = util::parseNumberArg(s.getValue(), "--seed");
		if (!(v >= 0 && v == std::floor(v)))
			throw util::UsageError("--seed: must be a whole number >= 0");
		seed = static_cast<uint64_t>(v);
	}
	out_dir = out.getValue();
	rawlog_path = rawlog.getValue();
	json = js.getValue();
	progress = !quiet.getValue() && !json;
}

int EkfSimApp::run(std::ostream& out)
{
	if (help_shown) return util::kExitOk;
	setup = eval::SimulationSetup::load(config_path);
	const auto world = world::World::load(world_path);
	const uint64_t s0 = seed.value_or(setup.sim.seed);
	run0_seed = s0;
	const auto report = [this](int done)
	{
		if (progress) std::cerr << "\rrun " << done << "/" << runs << std::flush;
	};
	results = eval::runMonteCarlo(world, setup, runs, s0, report);
	if (progress) std::cerr << "\n";
	summary = eval::summarise(results);
	writeOutputs(world);
	json ? printJson(out) : printTable(out);
	return util::kExitOk;
}

void EkfSimApp::writeOutputs(const world::World& world) const
{
	if (!out_dir.empty())
	{
		std::filesystem::create_directories(out_dir);
		detail::writeCsv(out_dir, results, summary);
		const auto name = std::filesystem::path(world_path).parent_path().filename().string();
		detail::writePathPlot(out_dir + "/paths.png",
		                      "mrolr-ekf-sim: world '" + name + "', run 0 of " +
		                          std::to_string(runs) + ", seed " + std::to_string(run0_seed),
		                      world, results.front());
		detail::writeTumFiles(out_dir, results.front());
	}
	if (!rawlog_path.empty()) detail::writeRawlog(rawlog_path, world, results.front(), setup);
}

void EkfSimApp::printJson(std::ostream& out) const
{
	const auto& m = summary;
	nlohmann::ordered_json j;
	j["runs"] = m.runs;
	j["steps"] = m.steps;
	j["nees_bounds"] = {m.nees_lo, m.nees_hi};
	j["nees_inside_fraction"] = m.nees_inside_fraction;
	j["slam_rms_position_m"] = m.slam_rms_position_m;
	j["slam_final_position_error_m"] = m.slam_final_position_error_m;
	j["slam_rms_heading_deg"] = m.slam_rms_heading_deg;
	j["dr_rms_position_m"] = m.dr_rms_position_m;
	j["dr_final_position_error_m"] = m.dr_final_position_error_m;
	j["mean_landmark_error_m"] = m.mean_landmark_error_m;
	j["mean_nis"] = m.mean_nis;
	j["features_added"] = m.features_added;
	j["features_deleted"] = m.features_deleted;
	j["outliers_rejected"] = m.outliers_rejected;
	j["outliers_injected"] = m.outliers_injected;
	j["ms_per_step"] = m.ms_per_step;
	j["update_method"] = slam::toString(setup.slam.update_method);
	j["jacobians"] = slam::toString(setup.slam.jacobians);
	out << j.dump(2) << "\n";
}

void EkfSimApp::printTable(std::ostream& out) const
{
	const auto& m = summary;
	const auto row = [&](const char* name, double v, const char* unit)
	{
		out << "  " << std::left << std::setw(38) << name << std::setprecision(6) << v << " "
		    << unit << "\n";
	};
	out << "mrolr-ekf-sim: " << m.runs << " runs of " << m.steps << " steps on " << world_path
	    << " (" << slam::toString(setup.slam.update_method) << " updates, "
	    << slam::toString(setup.slam.jacobians) << " Jacobians)\n";
	out << "  " << std::left << std::setw(38) << "mean NEES 95% bounds"
	    << "[" << m.nees_lo << ", " << m.nees_hi << "]\n";
	row("steps with mean NEES inside", m.nees_inside_fraction, "");
	row("mean NIS (3 expected)", m.mean_nis, "");
	row("SLAM RMS position error", m.slam_rms_position_m, "m");
	row("SLAM final position error", m.slam_final_position_error_m, "m");
	row("SLAM RMS heading error", m.slam_rms_heading_deg, "deg");
	row("dead-reckoning RMS position error", m.dr_rms_position_m, "m");
	row("dead-reckoning final position error", m.dr_final_position_error_m, "m");
	row("mean mapped-feature error", m.mean_landmark_error_m, "m");
	row("features added (all runs)", m.features_added, "");
	row("features deleted (all runs)", m.features_deleted, "");
	row("measurements rejected by the gate", m.outliers_rejected, "");
	row("outliers injected", m.outliers_injected, "");
	row("time per step", m.ms_per_step, "ms");
}

}  // namespace mrolr::apps
