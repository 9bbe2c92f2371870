// paths.png and the TUM trajectories of one simulated run (io/TopViewPlot.h, io/TumTrajectory.h).
#include "SimulationOutputs.h"

#include <mrolr/io/TopViewPlot.h>
#include <mrolr/io/TumTrajectory.h>

#include <algorithm>

namespace mrolr::apps::detail
{
namespace
{
using V2 = Eigen::Vector2d;
constexpr int kMaxPathEllipses = 40;  // a readable number of the vehicle's ellipses

std::vector<V2> pathOf(const eval::RunResult& run, Eigen::Vector3d eval::StepRecord::*field)
{
	std::vector<V2> out;
	for (const auto& s : run.steps) out.push_back((s.*field).head<2>());
	return out;
}
}  // namespace

void writePathPlot(const std::string& png, const std::string& title, const world::World& w,
                   const eval::RunResult& run)
{
	io::TopViewPlot plot(title);
	std::vector<V2> known, unknown;
	for (const auto& l : w.landmarks)
		(l.known ? known : unknown).emplace_back(l.p_LinW.z(), l.p_LinW.x());
	plot.addPoints("known landmark (true)", known, io::Marker::FilledSquare, {{0, 0, 0}, 1}, 9);
	plot.addPoints("landmark (true)", unknown, io::Marker::Square, {{0, 0, 0}, 2}, 9);
	plot.addPath("dead reckoning", pathOf(run, &eval::StepRecord::dead_reckoning),
	             {{0, 0, 220}, 2});
	plot.addPath("true path", pathOf(run, &eval::StepRecord::truth), {{0, 160, 0}, 2});
	plot.addPath("EKF-SLAM estimate", pathOf(run, &eval::StepRecord::estimate), {{200, 0, 0}, 2});
	std::vector<Eigen::Matrix2d> P;
	for (const auto& s : run.steps) P.push_back(io::zxBlockOfVehicle(s.P_vv));
	plot.addEllipses95("estimate, 95 % ellipse", pathOf(run, &eval::StepRecord::estimate), P,
	                   {{200, 0, 0}, 2}, kMaxPathEllipses);
	std::vector<V2> mapped;
	std::vector<Eigen::Matrix2d> P_map;
	for (size_t i = 0; i < run.final_positions.size(); ++i)
		mapped.emplace_back(run.final_positions[i].z(), run.final_positions[i].x()),
		    P_map.push_back(io::zxMarginalOfPoint(run.final_covariances[i]));
	plot.addPoints("feature (mapped)", mapped, io::Marker::Cross, {{200, 0, 200}, 2}, 10);
	plot.addEllipses95("feature, 95 % ellipse", mapped, P_map, {{200, 0, 200}, 2});
	plot.write(png);
}

void writeTumFiles(const std::string& dir, const eval::RunResult& run)
{
	std::vector<io::StampedVehicle> truth, estimate, odometry;
	double t_s = 0;
	for (size_t k = 0; k < run.steps.size(); ++k)
	{
		if (k < run.controls_odometry.size()) t_s += run.controls_odometry[k].z();
		truth.push_back({t_s, run.steps[k].truth});
		estimate.push_back({t_s, run.steps[k].estimate});
		odometry.push_back({t_s, run.steps[k].dead_reckoning});
	}
	io::writeTum(dir + "/truth.tum", truth);
	io::writeTum(dir + "/estimate.tum", estimate);
	io::writeTum(dir + "/odometry.tum", odometry);
}

}  // namespace mrolr::apps::detail
