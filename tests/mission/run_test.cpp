// Whole simulated missions: the default one through the app (the lap, from images, with its
// outputs), an absent target, lost features, an object out of the arm's reach, wheel slip, and a
// bad configuration that stops before anything moves.
#include "MissionTestConfig.h"

#include <mrolr/apps/MissionApp.h>
#include <mrolr/io/Rawlog.h>
#include <mrolr/io/TumTrajectory.h>
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
	const auto path = mission::test::freshTempDir("mission_test_absent") + "/world.ini";
	std::ofstream(path) << text;
	return path;
}

const eval::ObjectTruth& objectNamed(const eval::MissionTruth& t, const std::string& name)
{
	for (const auto& o : t.objects)
		if (o.name == name) return o;
	throw std::runtime_error("no object " + name);
}
}  // namespace

TEST(MissionRun, TheDefaultMissionDrivesTheLapFromImagesAndBringsTheTargetHome)
{
	const auto dir = mission::test::freshTempDir("mission_test_present");
	apps::MissionApp app;
	app.initialize({"mrolr-mission", "--config", mission::test::configDir() + "/mission_sim.ini",
	                "--out", dir, "--quiet", "--json"});
	std::ostringstream out, progress;
	EXPECT_EQ(app.run(out, progress), 0) << out.str();
	const auto& r = app.result;
	const auto& j = app.report;
	// what the robot believes ...
	EXPECT_EQ(r.navigation_source, "images");
	EXPECT_GT(app.options.plan.route.size(), 3u);  // the lap, not a straight line
	EXPECT_TRUE(r.found);
	EXPECT_TRUE(r.retrieved);
	EXPECT_TRUE(r.place.placed) << r.place.reason;  // put down on its deck, the arm parked
	EXPECT_GT(r.place.width_before_mm, app.options.retrieval.min_held_width_mm);
	EXPECT_TRUE(r.returned_home);
	EXPECT_TRUE(r.retrieval.verified);
	// ... and what eval found
	EXPECT_TRUE(j["eval"]["confirms"].get<bool>());
	EXPECT_EQ(j["found_instance"], app.options.target);
	EXPECT_LT(j["final_position_error_m"].get<double>(), app.options.home_tolerance_m);
	EXPECT_LT(j["object_translation_error_mm"].get<double>(), 15.0);
	EXPECT_TRUE(j["eval"]["object_on_board"].get<bool>());  // it rode home on the deck
	EXPECT_EQ(j["eval"]["on_board_instance"], app.options.target);
	EXPECT_GT(j["nis"]["count"].get<int>(), 100);
	const auto written = nlohmann::json::parse(std::ifstream(dir + "/report.json"));
	for (const char* key :
	     {"success", "target", "found", "retrieved", "returned_home", "final_position_error_m",
	      "object_rotation_error_deg", "object_translation_error_mm", "grasp_correction_mm",
	      "stages", "compute_seconds", "simulated_seconds", "T_OinA", "timeline", "robot", "eval",
	      "nis", "navigation_source", "navigation_pairs"})
		EXPECT_TRUE(written.contains(key)) << key;
	EXPECT_TRUE(written["success"].get<bool>());
	for (const char* f : {"report.md", "trajectory.png", "mission.3Dscene", "mission.rawlog"})
		EXPECT_GT(fs::file_size(dir + "/" + f), 100u) << f;
	// The TUM files hold the path as the robot estimated it and as it was, on the base's clock:
	// from them a user's tools find eval's final position error.
	const auto estimate_tum = io::readTum(dir + "/estimate.tum");
	const auto truth_tum = io::readTum(dir + "/truth.tum");
	ASSERT_EQ(estimate_tum.size(), r.path.size());
	for (size_t i = 0; i < estimate_tum.size(); ++i)
	{
		EXPECT_NEAR(estimate_tum[i].time_s, r.path[i].device_time_s, 1e-9);
		EXPECT_LT((estimate_tum[i].xv_zxphi.head<2>() - r.path[i].estimate.head<2>()).norm(),
		          1e-9);
	}
	ASSERT_FALSE(truth_tum.empty());
	EXPECT_NEAR((truth_tum.back().xv_zxphi - estimate_tum.back().xv_zxphi).head<2>().norm(),
	            j["final_estimate_error_m"].get<double>(), 1e-6);
	EXPECT_NEAR(truth_tum.back().time_s, estimate_tum.back().time_s, 1e-9);
	// One stereo pair per sweep view and one for the visual verification's re-observation, and
	// those of the obstacle looks, stored as external images.
	ASSERT_EQ(mission::countShots(r.shots, mission::StereoShot::Purpose::Table),
	          static_cast<size_t>(r.search.views) + 1);
	EXPECT_EQ(mission::countShots(r.shots, mission::StereoShot::Purpose::Obstacle),
	          static_cast<size_t>(r.obstacle.looks));
	// Every stereo pair the robot received is recorded (navigation's too), stored as external
	// images beside the pictures of its decisions.
	const size_t pairs = r.shots.size() + size_t(r.navigation_pairs);
	size_t images = 0;
	for (const auto& e : fs::directory_iterator(dir + "/mission_Images"))
		images += e.path().filename().string().rfind("BISIGHT_", 0) == 0;
	EXPECT_EQ(images, 2 * pairs);
	EXPECT_GE(j["recording"]["images"].get<size_t>(), images);
	// The rawlog reads back as records: one per odometry reading and per stereo pair, each with
	// the truth of its step (the world side's).
	const auto records = io::readRawlog(dir + "/mission.rawlog");
	size_t stereo = 0, truth = 0;
	for (const auto& rec : records)
		stereo += rec.has_stereo && rec.left.getWidth() == 640, truth += rec.true_zxphi.has_value();
	EXPECT_EQ(stereo, pairs);
	EXPECT_EQ(records.size() - stereo, r.path.size());
	EXPECT_EQ(truth, records.size());
	mrpt::opengl::COpenGLScene scene;
	ASSERT_TRUE(scene.loadFromFile(dir + "/mission.3Dscene"));
	EXPECT_TRUE(scene.getByName("path.true"));
	EXPECT_TRUE(scene.getByName("arm"));
	EXPECT_TRUE(scene.getByName("recognised." + app.options.target));
}

TEST(MissionRun, AbsentTargetIsReportedAndTheRobotReturnsHome)
{
	auto cfg = mission::test::defaultMissionConfig();
	cfg.write("search", "cover_table", "false");  // the fixed pans: a known number of views
	const auto plan = mission::test::planWith(
	    {{"plan", "route", "W0"}, {"waypoints", "S2", "2.45 0.0 180"}, {"plan", "stations", "W5 S2"}});
	const auto run = mission::test::runMission(
	    cfg, plan, worldWithout(mission::test::optionsFrom(cfg).target));
	const auto& r = run.r;
	EXPECT_FALSE(r.found);
	EXPECT_FALSE(r.retrieved);
	EXPECT_FALSE(r.success);
	EXPECT_EQ(r.stations_searched, 2);
	EXPECT_FALSE(r.retrieval.attempted);
	EXPECT_TRUE(r.returned_home);
	EXPECT_TRUE(run.report["eval"]["returned_home"].get<bool>());
	EXPECT_NE(r.failure.find("not found"), std::string::npos) << r.failure;
	// nine views at each of the two stations (five pans, then four between)
	EXPECT_EQ(mission::countShots(r.shots, mission::StereoShot::Purpose::Table), 18u);
}

TEST(MissionRun, LostFeaturesAreDeletedReplacedAndTheRobotStillGetsHome)
{
	auto cfg = mission::test::defaultMissionConfig();
	cfg.write("navigation", "landmark_sensor", "ideal_sim");
	cfg.write("navigation", "lost_feature_probability", "0.5");
	const auto run = mission::test::runMission(cfg, mission::test::shortRoute());
	const auto& r = run.r;
	// more than half of a feature's last ten searches fail: the 5.7 rule deletes it
	EXPECT_GT(r.measurements_lost, 20);
	EXPECT_GT(r.features_deleted, 0);
	EXPECT_GT(r.measurements, 0);
	EXPECT_TRUE(r.found);
	EXPECT_TRUE(r.returned_home);
	EXPECT_LT(run.report["final_position_error_m"].get<double>(), run.o.home_tolerance_m);
	EXPECT_LT(run.report["final_estimate_error_m"].get<double>(), run.o.home_tolerance_m);
}

TEST(MissionRun, UnreachableObjectIsReportedAndTheArmDoesNotMove)
{
	auto cfg = mission::test::defaultMissionConfig();
	cfg.write("arm_mount", "T_C0inA", "0 0 1 -1500    1 0 0 1200    0 1 0 711");
	cfg.write("docking", "drive_to_reach", "false");  // retrieval_mission_test docks
	const auto run = mission::test::runMission(cfg, mission::test::shortRoute());
	const auto& r = run.r;
	EXPECT_TRUE(r.found);
	EXPECT_FALSE(r.retrieval.feasible);
	EXPECT_FALSE(r.retrieval.attempted);
	EXPECT_FALSE(r.retrieved);
	ASSERT_FALSE(r.retrieval.reasons.empty());
	EXPECT_NE(r.failure.find("not feasible"), std::string::npos) << r.failure;
	const auto& cube = objectNamed(run.truth, run.o.target);
	EXPECT_LT((cube.T_OinW.translation() - cube.T_OinW_start.translation()).norm(), 1e-12);
	EXPECT_TRUE(r.returned_home);
}

TEST(MissionRun, MalformedConfigStopsBeforeAnythingMoves)
{
	const auto dir = mission::test::freshTempDir("mission_test_malformed");
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
double meanError(const mission::test::Run& run, Eigen::Vector3d mission::PathSample::*pose)
{
	const auto truth = mission::test::truePath(run);
	double sum = 0;
	for (size_t i = 0; i < run.r.path.size(); ++i)
		sum += ((run.r.path[i].*pose).head<2>() - truth[i].head<2>()).norm();
	return sum / static_cast<double>(run.r.path.size());
}
}  // namespace

TEST(MissionRun, SlamFromImagesOutlivesWheelSlipBurstsThatDeadReckoningDoesNot)
{
	auto cfg = mission::test::defaultMissionConfig();
	cfg.write("sim_base", "slip_probability", "0.15");
	cfg.write("search", "scene_sensor", "exact_sim");  // navigation is under test here
	cfg.write("search", "render_stereo", "false");
	const auto slam = mission::test::runMission(cfg);
	EXPECT_GT(slam.r.map.size(), 3u);
	// Same run, same truth: the filter's estimate against the odometry it was given.
	const double e_slam = meanError(slam, &mission::PathSample::estimate);
	const double e_odo = meanError(slam, &mission::PathSample::odometry);
	EXPECT_LT(e_slam, 0.5 * e_odo) << e_slam << " vs " << e_odo;
	EXPECT_LT(slam.report["final_estimate_error_m"].get<double>(),
	          slam.report["dead_reckoning_error_m"].get<double>());
	cfg.write("mission", "mode", "dead_reckoning");
	const auto dr = mission::test::runMission(cfg, mission::test::shortRoute());
	EXPECT_TRUE(dr.r.map.empty());
	for (const auto& s : dr.r.path) EXPECT_EQ(s.estimate, s.odometry);
}
