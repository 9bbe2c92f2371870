// mrolr-slam --out DIR: trajectory.csv, map.csv, decisions.csv, paths.png, decisions.rawlog and
// slam.3Dscene.
#include <mrolr/apps/SlamApp.h>
#include "SlamRecordings.h"

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

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

/** Top view (z up the image, x to the left as in W): true (green), SLAM (red), dead reckoning
 * (blue) and mapped features (black). */
void writePlot(const std::string& dir, const std::vector<SlamStepLog>& steps)
{
	const double scale = 80, zmin = -3, xmax = 4;  // px per metre, view origin
	cv::Mat img(720, 720, CV_8UC3, cv::Scalar(255, 255, 255));
	auto px = [&](const Eigen::Vector3d& x)
	{ return cv::Point(int((xmax - x[1]) * scale), int(img.rows - (x[0] - zmin) * scale)); };
	auto path = [&](auto member, cv::Scalar colour)
	{
		for (size_t k = 1; k < steps.size(); ++k)
			cv::line(img, px(steps[k - 1].*member), px(steps[k].*member), colour, 2, cv::LINE_AA);
	};
	path(&SlamStepLog::x_dr, {255, 0, 0});
	path(&SlamStepLog::x_true, {0, 160, 0});
	path(&SlamStepLog::x_est, {0, 0, 255});
	cv::putText(img, "true (green)  SLAM (red)  dead reckoning (blue)", {10, 20},
	            cv::FONT_HERSHEY_SIMPLEX, 0.5, {0, 0, 0});
	if (!cv::imwrite((std::filesystem::path(dir) / "paths.png").string(), img))
		throw std::runtime_error(dir + "/paths.png: cannot write");
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
	writePlot(out_dir, steps);
	const std::filesystem::path dir(out_dir);
	writeDecisionRawlog((dir / "decisions.rawlog").string(), steps);
	writeSlamScene((dir / "slam.3Dscene").string(), steps, map, true_landmarks);
}

}  // namespace mrolr::apps
