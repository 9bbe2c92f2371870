#include "SimCommon.h"

#include <mrolr/apps/SimApp.h>
#include <mrolr/model/WireFrameIO.h>
#include <mrolr/sim/ObjectWireFrame.h>
#include <mrolr/sim/SimTurntable.h>
#include <mrolr/stereo/HeadCalibration.h>

#include <mrpt/config/CConfigFile.h>
#include <mrpt/config/CConfigFileMemory.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <ostream>
#include <sstream>

namespace mrolr::apps
{
using namespace simdetail;
namespace fs = std::filesystem;

namespace
{
std::string objectPath(const std::string& world_path, const std::string& object)
{
	if (fs::exists(object)) return object;  // a path to an object definition
	std::string dir = SimApp::projectFile("datasets/objects");
	if (!world_path.empty()) dir = world::World::load(world_path).objects_dir;
	return (fs::path(dir) / (object + ".ini")).string();
}

nlohmann::json calibrationJson(const sim::SimTurntable& t, const geometry::BiSightHead& head,
                               double step_deg, int views)
{
	const auto a = t.headAngles();
	const auto& c = head.camera();
	return {{"frames",
	         "T: turntable (z up the axis, origin on the disc top); O = T rotated by "
	         "angle_deg about z; L, R, C0 thesis axes; metres"},
	        {"step_deg", step_deg},
	        {"views", views},
	        {"head_rad", {a.pan, a.tilt, a.verg_left, a.verg_right}},
	        {"intrinsics",
	         {{"focal_px_u", c.focal_px_u},
	          {"focal_px_v", c.focal_px_v},
	          {"u0_px", c.u0_px},
	          {"v0_px", c.v0_px}}},
	        {"T_TinL", matrixJson(t.T_TinL())},
	        {"T_TinC0", matrixJson(t.T_TinC0())},
	        {"T_LinC0", matrixJson(head.T_LinC0(a))},
	        {"T_RinC0", matrixJson(head.T_RinC0(a))}};
}

std::string joinDoubles(const double* v, int n)
{
	std::ostringstream s;
	s.precision(17);
	for (int i = 0; i < n; ++i) s << (i ? " " : "") << v[i];
	return s.str();
}

/** DIR/turntable.ini as `mrolr-model build --turntable` reads it (docs/model.md): p_T = R_TfromL ·
 * p_L + t_LinT_mm, L in thesis axes; view k shows the object turned by angles_deg[k] about T's z.
 */
void writeModelTurntableIni(const std::string& path, const std::string& object,
                            const Eigen::Isometry3d& T_TinL, const std::vector<double>& angles_deg,
                            const std::vector<std::string>& view_names)
{
	const Eigen::Isometry3d T_LinT = T_TinL.inverse();  // metres
	const Eigen::Matrix<double, 3, 3, Eigen::RowMajor> R_TfromL = T_LinT.linear();
	const Eigen::Vector3d t_LinT_mm = 1000.0 * T_LinT.translation();
	mrpt::config::CConfigFileMemory cfg;
	cfg.write("turntable", "object", object);
	cfg.write("turntable", "calib", std::string("calib.ini"));
	cfg.write("turntable", "R_TfromL", joinDoubles(R_TfromL.data(), 9));
	cfg.write("turntable", "t_LinT_mm", joinDoubles(t_LinT_mm.data(), 3));
	cfg.write("turntable", "views", int(view_names.size()));
	cfg.write("turntable", "truth", object + "_truth.wf");
	for (size_t k = 0; k < view_names.size(); ++k)
	{
		const std::string sec = "view_" + std::to_string(k);
		cfg.write(sec, "left", view_names[k] + "_left.png");
		cfg.write(sec, "right", view_names[k] + "_right.png");
		cfg.write(sec, "angle_deg", angles_deg[k]);
	}
	std::ofstream(path) << cfg.getContent();
}
}  // namespace

int SimApp::runTurntable(std::ostream& out)
{
	const auto shape = world::ObjectShape::load(objectPath(world_path, turntable_object));
	const geometry::BiSightHead head(geometry::BiSightOptions::fromFile(bisight_path));
	sim::SimTurntableOptions to;
	to.loadFromConfigFile(mrpt::config::CConfigFile(sim_config_path), "sim_turntable");
	sim::StereoRenderer renderer(head, renderOptions(sim_config_path));
	sim::SimTurntable table(renderer, shape, to);
	fs::create_directories(out_path);
	const auto p = [&](const std::string& n) { return (fs::path(out_path) / n).string(); };
	const int views = int(std::lround(360.0 / to.step_deg));
	std::vector<double> angles_deg;
	std::vector<std::string> view_names;
	for (int k = 0; k < views; ++k)
	{
		const auto t0 = std::chrono::steady_clock::now();
		const auto img = table.grab();
		render_s += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
		char name[32];
		std::snprintf(name, sizeof(name), "view_%03d", int(std::lround(table.angleDeg())));
		angles_deg.push_back(table.angleDeg());
		view_names.push_back(name);
		saveImage(img.left, p(std::string(name) + "_left.png"));
		saveImage(img.right, p(std::string(name) + "_right.png"));
		files_written.push_back(p(std::string(name) + "_{left,right}.png"));
		++frames_written;
		table.rotateBy(to.step_deg);
		if (!json) out << "\rview " << k + 1 << "/" << views << std::flush;
	}
	if (!json) out << "\n";
	std::ofstream(p("calibration.json"))
	    << calibrationJson(table, head, to.step_deg, views).dump(2) << "\n";
	model::saveWireFrame(sim::objectWireFrame(shape), p(shape.name + "_truth.wf"));
	stereo::saveStereoCalibration(stereo::calibrationFromHead(head, table.headAngles()),
	                              p("calib.ini"));
	writeModelTurntableIni(p("turntable.ini"), shape.name, table.T_TinL(), angles_deg, view_names);
	files_written.push_back(p("calib.ini"));
	files_written.push_back(p("turntable.ini"));
	files_written.push_back(p("calibration.json"));
	files_written.push_back(p(shape.name + "_truth.wf"));
	return 0;
}

}  // namespace mrolr::apps
