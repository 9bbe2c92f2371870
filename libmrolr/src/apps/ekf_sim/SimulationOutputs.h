#pragma once
// Files written by mrolr-ekf-sim: per-step CSV, the path plot and the MRPT rawlog of one run.

#include <mrolr/eval/EkfSimulation.h>

#include <string>
#include <vector>

namespace mrolr::apps::detail
{
/** steps.csv: one row per run and step (truth, estimate, covariance diagonal, NEES, dead
 * reckoning); nees.csv: the mean NEES per step with its bounds. */
void writeCsv(const std::string& dir, const std::vector<eval::RunResult>& runs,
              const eval::MonteCarloSummary& summary);

/** Top view (io/TopViewPlot.h) of the true, estimated and dead-reckoned paths of @p run with the
 * vehicle's 95 % position ellipses, the true landmarks (known ones filled) and the mapped features
 * with their 95 % ellipses. */
void writePathPlot(const std::string& png, const std::string& title, const world::World& world,
                   const eval::RunResult& run);

/** truth.tum, estimate.tum and odometry.tum of @p run in @p dir (io/TumTrajectory.h), stamped
 * with the simulated time (the sum of the steps' dt). */
void writeTumFiles(const std::string& dir, const eval::RunResult& run);

/** The run as an MRPT rawlog: per step a CActionRobotMovement2D from the commanded odometry and a
 * CSensoryFrame with one CObservationBearingRange holding the measured features (docs/slam.md). */
void writeRawlog(const std::string& path, const world::World& world, const eval::RunResult& run,
                 const eval::SimulationSetup& setup);

}  // namespace mrolr::apps::detail
