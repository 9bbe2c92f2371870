// Whole simulated missions: target present (through the app, with its outputs), target absent,
// object out of the arm's reach, and a bad configuration that stops before anything moves.
#include "MissionTestConfig.h"

#include <mrolr/apps/MissionApp.h>
#include <mrolr/io/Rawlog.h>
#include <mrolr/mission/Mission.h>
#include <mrolr/util/Config.h>

#include <gtest/gtest.h>
#include <mrpt/opengl/COpenGLScene.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

using namespace mrolr;
namespace fs = std::filesystem;

namespace
{
std::string tempDir(const std::string& name)
{
	const auto d = fs::temp_directory_path() / ("mrolr_mission_test_" + name);
	fs::remove_all(d);
	fs::create_directories(d);
	return d.string();
}

/** The lab world without the object @p name, written to a temporary folder. */
std::string worldWithout(const std::string& name)
{
	std::ifstream f(std::string(MROLR_SOURCE_DIR) + "/maps/lab/world.ini");
	std::stringstream s;
	s << f.rdbuf();
	std::string text =
	    std::regex_replace(s.str(), std::regex("\\[object\\." + name + "\\][^\\[]*"), "");
	text =
	    std::regex_replace(text, std::regex("objects_dir = [^\\n]*"),
	                       "objects_dir = " + std::string(MROLR_SOURCE_DIR) + "/datasets/objects");
	text = std::regex_replace(text, std::regex("texture = textures/"),
	                          "texture = " + std::string(MROLR_SOURCE_DIR) + "/maps/lab/textures/");
	const auto path = tempDir("absent") + "/world.ini";
	std::ofstream(path) << text;
	return path;
}

/** Where the target (placed under its model's name in the lab) stands at the start. */
Eigen::Vector3d targetStart(const mission::MissionOptions& o)
{
	return mission::placedObjects(o.world).at(o.target).T_OinW.translation();
}
}  // namespace

TEST(MissionRun, TargetPresentIsFoundRetrievedAndBroughtHome)
{
	const auto dir = tempDir("present");
	apps::MissionApp app;
	app.initialize({"mrolr-mission", "--config", mission::test::configDir() + "/mission_sim.ini",
	                "--out", dir, "--quiet", "--json"});
	std::ostringstream out, progress;
	EXPECT_EQ(app.run(out, progress), 0) << out.str();
	const auto& r = app.result;
	EXPECT_TRUE(r.found);
	EXPECT_EQ(r.found_instance, app.options.target);
	EXPECT_TRUE(r.retrieved);
	EXPECT_TRUE(r.returned_home);
	EXPECT_LT(r.final_position_error_m, app.options.home_tolerance_m);
	EXPECT_LT(r.search.translation_error_mm, 15.0);
	EXPECT_LT(r.search.rotation_error_deg, 5.0);
	EXPECT_TRUE(r.retrieval.verified);
	// The target came home on the base: now within 0.6 m of home, not on the table.
	const Eigen::Vector3d p = r.final_objects.at(app.options.target).T_OinW.translation();
	EXPECT_LT(std::hypot(p.z() - r.home.x(), p.x() - r.home.y()), 0.6);
	EXPECT_GT((p - targetStart(app.options)).norm(), 0.5);
	const auto j = nlohmann::json::parse(std::ifstream(dir + "/report.json"));
	for (const char* key :
	     {"success", "target", "found", "retrieved", "returned_home", "final_position_error_m",
	      "object_rotation_error_deg", "object_translation_error_mm", "grasp_correction_mm",
	      "stages", "compute_seconds", "simulated_seconds", "T_OinA", "timeline"})
		EXPECT_TRUE(j.contains(key)) << key;
	EXPECT_TRUE(j["success"].get<bool>());
	for (const char* f : {"report.md", "trajectory.png", "mission.3Dscene", "mission.rawlog"})
		EXPECT_GT(fs::file_size(dir + "/" + f), 100u) << f;
	// One stereo pair per sweep view and one for the visual verification's re-observation (the
	// default mission reconstructs each view from its pair), stored as external images.
	ASSERT_EQ(app.options.search.scene_source, "reconstructed");
	ASSERT_EQ(r.shots.size(), static_cast<size_t>(r.search.views) + 1);
	size_t images = 0;
	for (const auto& e : fs::directory_iterator(dir + "/mission_Images"))
		images += e.path().extension() == ".png";
	EXPECT_EQ(images, 2 * r.shots.size());
	// The rawlog reads back: one record per motion step and per stereo pair.
	const auto records = io::readRawlog(dir + "/mission.rawlog");
	EXPECT_EQ(records.size(), r.path.size() + r.shots.size());
	size_t stereo = 0;
	for (const auto& rec : records) stereo += rec.has_stereo && rec.left.getWidth() == 640;
	EXPECT_EQ(stereo, r.shots.size());
	mrpt::opengl::COpenGLScene scene;
	ASSERT_TRUE(scene.loadFromFile(dir + "/mission.3Dscene"));
	EXPECT_TRUE(scene.getByName("path.true"));
	EXPECT_TRUE(scene.getByName("arm"));
	EXPECT_TRUE(scene.getByName("recognised." + app.options.target));
}

TEST(MissionRun, AbsentTargetIsReportedAndTheRobotReturnsHome)
{
	auto cfg = mission::test::defaultMissionConfig();
	cfg.write("mission", "world_file", worldWithout(mission::test::optionsFrom(cfg).target));
	const auto o = mission::test::optionsFrom(cfg);
	mission::Mission m(o);
	const auto r = m.run();
	EXPECT_FALSE(r.found);
	EXPECT_FALSE(r.retrieved);
	EXPECT_FALSE(r.success);
	EXPECT_EQ(r.stations_searched, static_cast<int>(o.stations.size()));
	EXPECT_FALSE(r.retrieval.attempted);
	EXPECT_TRUE(r.returned_home);
	EXPECT_NE(r.failure.find("not found"), std::string::npos) << r.failure;
	EXPECT_EQ(r.shots.size(), 10u);  // five views at each of the two stations
}

TEST(MissionRun, LostFeaturesAreDeletedReplacedAndTheRobotStillGetsHome)
{
	auto cfg = mission::test::defaultMissionConfig();
	cfg.write("navigation", "lost_feature_probability", "0.5");
	const auto o = mission::test::optionsFrom(cfg);
	const auto r = mission::Mission(o).run();
	// more than half of a feature's last ten searches fail: the 5.7 rule deletes it
	EXPECT_GT(r.measurements_lost, 20);
	EXPECT_GT(r.features_deleted, 0);
	EXPECT_GT(r.measurements, 0);
	EXPECT_TRUE(r.found);
	EXPECT_TRUE(r.returned_home);
	EXPECT_LT(r.final_position_error_m, o.home_tolerance_m);
	EXPECT_LT(r.final_estimate_error_m, o.home_tolerance_m);
}

TEST(MissionRun, UnreachableObjectIsReportedAndTheArmDoesNotMove)
{
	auto cfg = mission::test::defaultMissionConfig();
	cfg.write("arm_mount", "T_C0inA", "0 0 1 -1500    1 0 0 1200    0 1 0 711");
	cfg.write("mission", "search_stations", "W5");
	const auto o = mission::test::optionsFrom(cfg);
	mission::Mission m(o);
	const auto r = m.run();
	EXPECT_TRUE(r.found);
	EXPECT_FALSE(r.retrieval.feasible);
	EXPECT_FALSE(r.retrieval.attempted);
	EXPECT_FALSE(r.retrieved);
	ASSERT_FALSE(r.retrieval.reasons.empty());
	EXPECT_NE(r.failure.find("not feasible"), std::string::npos) << r.failure;
	EXPECT_LT((r.final_objects.at(o.target).T_OinW.translation() - targetStart(o)).norm(), 1e-12);
	EXPECT_TRUE(r.returned_home);
}

TEST(MissionRun, MalformedConfigStopsBeforeAnythingMoves)
{
	const auto dir = tempDir("malformed");
	auto text = std::string("[mission]\nname = x\n");
	std::ofstream(dir + "/bad.ini") << text;
	apps::MissionApp app;
	app.initialize({"mrolr-mission", "--config", dir + "/bad.ini", "--out", dir + "/out"});
	std::ostringstream out, progress;
	EXPECT_THROW(app.run(out, progress), util::ConfigError);
	EXPECT_FALSE(fs::exists(dir + "/out"));
	EXPECT_TRUE(app.result.path.empty());
}

namespace
{
/** Mean distance (m) from the truth over a run's path of the estimate or the odometry. */
double meanError(const mission::MissionResult& r, Eigen::Vector3d mission::PathSample::*pose)
{
	double sum = 0;
	for (const auto& s : r.path) sum += ((s.*pose).head<2>() - s.truth.head<2>()).norm();
	return sum / static_cast<double>(r.path.size());
}
}  // namespace

TEST(MissionRun, SlamOutlivesWheelSlipBurstsThatDeadReckoningDoesNot)
{
	auto cfg = mission::test::defaultMissionConfig();
	cfg.write("sim_base", "slip_probability", "0.15");
	cfg.write("mission", "route", "world");  // the whole lap round the lab first
	cfg.write("mission", "search_stations", "W5");
	const auto slam = mission::Mission(mission::test::optionsFrom(cfg)).run();
	EXPECT_GT(slam.map.size(), 3u);
	// Same run, same truth: the filter's estimate against the odometry it was given.
	const double e_slam = meanError(slam, &mission::PathSample::estimate);
	const double e_odo = meanError(slam, &mission::PathSample::odometry);
	EXPECT_LT(e_slam, 0.5 * e_odo) << e_slam << " vs " << e_odo;
	EXPECT_LT(slam.final_estimate_error_m, slam.dead_reckoning_error_m);
	cfg.write("mission", "mode", "dead_reckoning");
	const auto dr = mission::Mission(mission::test::optionsFrom(cfg)).run();
	EXPECT_TRUE(dr.map.empty());
	for (const auto& s : dr.path) EXPECT_EQ(s.estimate, s.odometry);
}
