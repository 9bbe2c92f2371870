// mrolr-map: a plan of a world from one drive. The route comes from the world as a user would
// write it; the known features are the robot's own triangulations, never the world's positions,
// and differ from the truth by amounts consistent with their stored standard deviations.
#include <mrolr/apps/MapApp.h>
#include <mrolr/mission/Plan.h>
#include <mrolr/world/World.h>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <sstream>

using namespace mrolr;
namespace fs = std::filesystem;

TEST(MrolrMap, TheOfficesPlanHoldsTheRobotsOwnWellMappedFeatures)
{
	const auto dir = fs::temp_directory_path() / "mrolr_map_test";
	fs::remove_all(dir);
	const std::string root = MROLR_SOURCE_DIR;
	apps::MapApp app;
	app.initialize({"mrolr-map", "--world", root + "/maps/office/world.ini", "--out",
	                (dir / "plan.ini").string(), "--config", root + "/config/mission_sim.ini",
	                "--quiet"});
	std::ostringstream out, progress;
	ASSERT_EQ(app.run(out, progress), 0) << out.str();
	const auto plan = mission::Plan::load((dir / "plan.ini").string());
	const auto w = world::World::load(root + "/maps/office/world.ini");
	// the user's plan of the place: the waypoints before the table's are the route
	ASSERT_EQ(plan.route.size(), 4u);
	EXPECT_EQ(plan.route.front().name, "W0");
	EXPECT_EQ(plan.stations.at(0).name, w.mission.table_waypoint);
	EXPECT_EQ(plan.home.name, w.mission.home_waypoint);
	ASSERT_EQ(plan.tables.size(), w.tables.size());
	// known features the robot mapped, with patches and viewpoints ...
	ASSERT_GE(plan.known_features.size(), 6u);
	for (const auto& k : plan.known_features)
	{
		EXPECT_EQ(k.patch.rows, 13) << k.id;
		EXPECT_TRUE(k.p_viewinW.has_value()) << k.id;
		EXPECT_LE(k.sigma_m.maxCoeff(), mission::MapBuilder::kMaxSavedSigma_m) << k.id;
		// ... none of them a landmark position of the world copied into the plan
		for (const auto& l : w.landmarks) EXPECT_GT((k.p_FinW - l.p_LinW).norm(), 1e-6) << k.id;
	}
	// the landmark the operator pointed at is there, under its name, within its bound
	const auto& r = app.report;
	EXPECT_EQ(r["locked"].size(), 1u);
	ASSERT_GE(r["eval"]["checked"].get<int>(), 1);
	EXPECT_EQ(r["eval"]["consistent_95"], r["eval"]["checked"]);
	for (const auto& f : r["eval"]["features"]) EXPECT_LT(f["error_norm_m"].get<double>(), 0.1);
	EXPECT_TRUE(fs::exists(dir / "map_report.json"));
}

TEST(MrolrMap, AWorldWithoutTheMissionsWaypointsIsAClearError)
{
	const auto dir = fs::temp_directory_path() / "mrolr_map_test_bad";
	fs::create_directories(dir);
	std::ofstream(dir / "world.ini")
	    << "[room]\nmin_m = -3 0 -2\nmax_m = 3 3 6\nobjects_dir = " << MROLR_SOURCE_DIR
	    << "/datasets/objects\n[waypoints]\nW0 = 0 0 0\n[mission]\ntarget = cup\n"
	       "table_waypoint = W9\nhome_waypoint = W0\n[table.t]\ncentre_m = 0 2\nsize_m = 1 1 0.75\n"
	       "[object.cup]\nmodel = cup\ntable = t\nposition_m = 0 2\n";
	apps::MapApp app;
	app.initialize({"mrolr-map", "--world", (dir / "world.ini").string(), "--out",
	                (dir / "plan.ini").string(), "--quiet"});
	std::ostringstream out, progress;
	try
	{
		app.run(out, progress);
		FAIL() << "no error";
	}
	catch (const std::exception& e)
	{
		EXPECT_NE(std::string(e.what()).find("W9"), std::string::npos) << e.what();
	}
}
