// mrolr-slam --out DIR: trajectory.csv, map.csv, decisions.csv, paths.png, truth.tum,
// estimate.tum, odometry.tum, decisions.rawlog and slam.3Dscene.
#include <mrolr/apps/SlamApp.h>
#include "SlamRecordings.h"

#include <mrolr/io/TopViewPlot.h>
#include <mrolr/io/TumTrajectory.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iomanip>

namespace mrolr::apps
{
namespace
{
std::ofstream openOut(const std::string& dir, const std::string& name)
{
	std::ofstream f(std::filesystem::path(dir) / name);
	if (!f) throw std::runtime_error(dir + "/" + name + ": cannot write");
	f << std::setprecision(9);
	return f;
}

void writeTrajectory(const std::string& dir, const std::vector<SlamStepLog>& steps)
{
	auto f = openOut(dir, "trajectory.csv");
	f << "step,true_z,true_x,true_phi,est_z,est_x,est_phi,dr_z,dr_x,dr_phi,var_z,var_x,var_phi\n";
	for (size_t k = 0; k < steps.size(); ++k)
	{
		const auto& s = steps[k];
		f << k;
		for (const auto* v : {&s.x_true, &s.x_est, &s.x_dr, &s.var_est})
			f << "," << (*v)[0] << "," << (*v)[1] << "," << (*v)[2];
		f << "\n";
	}
}

void writeDecisions(const std::string& dir, const std::vector<SlamStepLog>& steps)
{
	auto f = openOut(dir, "decisions.csv");
	f << "step,feature,vs,ellipse_u,ellipse_v,ellipse_area_px2,score_left,score_right,found,"
	     "accepted,"
	     "added,deleted,saccade,measurements_lost,waiting\n";
	for (size_t k = 0; k < steps.size(); ++k)
	{
		for (const auto& r : steps[k].records)
		{
			const auto& m = r.measurement;
			f << k << "," << r.label << "," << r.vs << "," << m.ellipse_left.centre.x() << ","
			  << m.ellipse_left.centre.y() << "," << m.ellipse_left.area() << "," << m.left.score
			  << "," << m.right.score << "," << m.found << "," << r.accepted << ",";
			for (const auto& a : r.added) f << a << " ";
			f << ",";
			for (const auto& d : r.deleted) f << d << " ";
			f << "," << r.saccade << "," << r.measurements_lost << "," << r.waiting << "\n";
		}
	}
}

std::vector<Eigen::Vector2d> pathOf(const std::vector<SlamStepLog>& steps,
                                    Eigen::Vector3d SlamStepLog::*field)
{
	std::vector<Eigen::Vector2d> out;
	for (const auto& s : steps) out.push_back((s.*field).head<2>());
	return out;
}

/** paths.png (io/TopViewPlot.h): the true, SLAM and dead-reckoned paths with the vehicle's 95 %
 * ellipses, the true landmarks and the mapped features with theirs. */
void writePlot(const std::string& dir, const std::string& title,
               const std::vector<SlamStepLog>& steps, const std::vector<MapFeature>& map,
               const std::vector<TrueLandmark>& true_landmarks)
{
	constexpr int kMaxPathEllipses = 40;
	io::TopViewPlot plot(title);
	std::vector<Eigen::Vector2d> landmarks;
	for (const auto& l : true_landmarks) landmarks.emplace_back(l.p_LinW.z(), l.p_LinW.x());
	plot.addPoints("landmark (true)", landmarks, io::Marker::Square, {{0, 0, 0}, 2}, 9);
	plot.addPath("dead reckoning", pathOf(steps, &SlamStepLog::x_dr), {{0, 0, 220}, 2});
	plot.addPath("true path", pathOf(steps, &SlamStepLog::x_true), {{0, 160, 0}, 2});
	plot.addPath("SLAM estimate", pathOf(steps, &SlamStepLog::x_est), {{200, 0, 0}, 2});
	std::vector<Eigen::Matrix2d> P;
	for (const auto& s : steps) P.push_back(s.var_est.head<2>().asDiagonal());
	plot.addEllipses95("estimate, 95 % ellipse (variances)", pathOf(steps, &SlamStepLog::x_est), P,
	                   {{200, 0, 0}, 2}, kMaxPathEllipses);
	std::vector<Eigen::Vector2d> mapped;
	std::vector<Eigen::Matrix2d> P_map;
	for (const auto& m : map)
		mapped.emplace_back(m.p_FinW.z(), m.p_FinW.x()), P_map.push_back(io::zxMarginalOfPoint(m.cov));
	plot.addPoints("feature (mapped)", mapped, io::Marker::Cross, {{200, 0, 200}, 2}, 10);
	plot.addEllipses95("feature, 95 % ellipse", mapped, P_map, {{200, 0, 200}, 2});
	plot.write((std::filesystem::path(dir) / "paths.png").string());
}

/** truth.tum, estimate.tum, odometry.tum (io/TumTrajectory.h); the timestamp is the step number
 * (the steps of mrolr-slam carry no clock). */
void writeTum(const std::string& dir, const std::vector<SlamStepLog>& steps)
{
	std::vector<io::StampedVehicle> truth, estimate, odometry;
	for (size_t k = 0; k < steps.size(); ++k)
		truth.push_back({double(k), steps[k].x_true}),
		    estimate.push_back({double(k), steps[k].x_est}),
		    odometry.push_back({double(k), steps[k].x_dr});
	const std::filesystem::path d(dir);
	io::writeTum((d / "truth.tum").string(), truth);
	io::writeTum((d / "estimate.tum").string(), estimate);
	io::writeTum((d / "odometry.tum").string(), odometry);
}
}  // namespace

void SlamApp::writeOutputs() const
{
	std::filesystem::create_directories(out_dir);
	writeTrajectory(out_dir, steps);
	writeDecisions(out_dir, steps);
	auto f = openOut(out_dir, "map.csv");
	f << "label,known,X,Y,Z,sd_X,sd_Y,sd_Z\n";
	for (const auto& m : map)
	{
		const Eigen::Vector3d sd = m.cov.diagonal().cwiseSqrt();
		f << m.label << "," << m.known << "," << m.p_FinW.x() << "," << m.p_FinW.y() << ","
		  << m.p_FinW.z() << "," << sd.x() << "," << sd.y() << "," << sd.z() << "\n";
	}
	writePlot(out_dir, run_title, steps, map, true_landmarks);
	writeTum(out_dir, steps);
	const std::filesystem::path dir(out_dir);
	writeDecisionRawlog((dir / "decisions.rawlog").string(), steps);
	writeSlamScene((dir / "slam.3Dscene").string(), steps, map, true_landmarks);
}

}  // namespace mrolr::apps
