#pragma once
/** `mrolr-ekf-sim`: Monte-Carlo runs of the active-vision EKF-SLAM simulator (thesis 5.4–5.9,
 * simulator module 1 of 6.8; the runs and their figures are eval/EkfSimulation.h):
 *
 *     mrolr-ekf-sim --world FILE [--config FILE] [--runs N] [--seed S] [--out DIR]
 *                   [--rawlog FILE] [--json]
 *
 * Prints the consistency and accuracy figures of the runs as a table (with a progress line on
 * stderr) or, with --json, as one JSON object. --out writes steps.csv, nees.csv, paths.png and
 * run 0's truth.tum, estimate.tum and odometry.tum (TUM format); --rawlog writes run 0 as an MRPT rawlog. Run r uses the seed S + 1000 r. */

#include <mrolr/eval/EkfSimulation.h>

#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

namespace mrolr::apps
{
class EkfSimApp
{
 public:
	/** Parses the command line (argv[0] first); throws util::UsageError for bad arguments. */
	void initialize(const std::vector<std::string>& args);
	/** Runs the simulations and prints the results to @p out; returns the exit code. */
	int run(std::ostream& out);

	// Inputs
	std::string world_path;
	std::string config_path;  ///< empty: config/ekf_sim.ini
	int runs = 1;
	std::optional<uint64_t> seed;  ///< default: [simulation] seed
	uint64_t run0_seed = 0;        ///< the seed run 0 used (set by run())
	std::string out_dir;
	std::string rawlog_path;
	bool json = false;
	bool progress = true;  ///< progress line on stderr (table mode only)
	bool help_shown = false;

	// Results
	eval::SimulationSetup setup;
	std::vector<eval::RunResult> results;
	eval::MonteCarloSummary summary;

	static std::string defaultConfigPath();

 private:
	void printTable(std::ostream& out) const;
	void printJson(std::ostream& out) const;
	void writeOutputs(const world::World& world) const;
};

}  // namespace mrolr::apps
