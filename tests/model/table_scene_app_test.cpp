// The table-scene measure from the command line (issue 6: "`mrolr-model stats --truth` prints
// them"): `mrolr-sim --snapshot` writes the pair, the left depth image and the exact objects'
// wire-frame in the left camera (truth_left.wf); `mrolr-model scene --head` builds the scene model
// in C0; `mrolr-model stats --truth --depth --head` compares it with the visible truth.
#include <mrolr/apps/ModelApp.h>
#include <mrolr/apps/SimApp.h>
#include <mrolr/util/Cli.h>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <string>

#include <unistd.h>
#include <sstream>

using namespace mrolr;
namespace fs = std::filesystem;

namespace
{
const std::string kHead = "0,-20,-8,8";

std::string snapshot()
{
	// one folder per test and process: ctest runs the tests in parallel processes, and other
	// build trees may run the same tests at the same time
	const std::string test = testing::UnitTest::GetInstance()->current_test_info()->name();
	const auto dir = (fs::path(testing::TempDir()) /
	                  ("mrolr_table_scene_app_" + test + "_" + std::to_string(::getpid())))
	                     .string();
	fs::remove_all(dir);
	apps::SimApp sim;
	sim.initialize({"mrolr-sim", "--world", std::string(MROLR_SOURCE_DIR) + "/maps/lab/world.ini",
	                "--snapshot", "--pose", "0.45,0,0", "--head", kHead, "--out", dir});
	std::ostringstream out;
	EXPECT_EQ(sim.run(out), 0) << out.str();
	return dir;
}

nlohmann::json runModel(const std::vector<std::string>& args)
{
	apps::ModelApp app;
	app.initialize(args);
	std::ostringstream out;
	EXPECT_EQ(app.run(out), 0);
	return nlohmann::json::parse(out.str());
}
}  // namespace

TEST(TableSceneApp, SnapshotSceneAndVisibleStats)
{
	const auto d = snapshot();
	ASSERT_TRUE(fs::exists(d + "/truth_left.wf"));
	runModel({"mrolr-model", "scene", "--left", d + "/left.png", "--right", d + "/right.png",
	          "--head", kHead, "--out", d + "/scene.wf", "--json"});
	const auto all = runModel({"mrolr-model", "stats", d + "/scene.wf", "--truth",
	                           d + "/truth_left.wf", "--head", kHead, "--json"});
	const auto seen =
	    runModel({"mrolr-model", "stats", d + "/scene.wf", "--truth", d + "/truth_left.wf",
	              "--depth", d + "/depth_left_mm.png", "--head", kHead, "--json"});
	const double visible = seen["visible_truth_length_mm"].get<double>();
	EXPECT_LT(visible, 0.8 * all["quality"]["true_length_mm"].get<double>());
	EXPECT_NEAR(seen["quality"]["true_length_mm"].get<double>(), visible, 1e-6);
	// the same measure as model_table_scene_test (--head: with the up direction); the view is one
	// of its set, where no view falls under 30 %
	EXPECT_GE(seen["quality"]["recovered_fraction"].get<double>(), 0.30);
	EXPECT_GT(seen["quality"]["recovered_fraction"].get<double>(),
	          all["quality"]["recovered_fraction"].get<double>());
	EXPECT_EQ(seen["visible_in"], "left");
	// what both cameras see (--depth-right): a part of what the left one sees, without the edges
	// only the left camera sees, which no stereo pair reconstructs; so more of it is recovered
	ASSERT_TRUE(fs::exists(d + "/depth_right_mm.png"));
	const auto both =
	    runModel({"mrolr-model", "stats", d + "/scene.wf", "--truth", d + "/truth_left.wf",
	              "--depth", d + "/depth_left_mm.png", "--depth-right", d + "/depth_right_mm.png",
	              "--head", kHead, "--json"});
	EXPECT_EQ(both["visible_in"], "both");
	EXPECT_LT(both["visible_truth_length_mm"].get<double>(), visible);
	EXPECT_GT(both["quality"]["recovered_fraction"].get<double>(),
	          seen["quality"]["recovered_fraction"].get<double>());
}

TEST(TableSceneApp, StatsRefuseMixedFramesAndMissingInputs)
{
	const auto d = snapshot();
	runModel({"mrolr-model", "scene", "--left", d + "/left.png", "--right", d + "/right.png",
	          "--head", kHead, "--out", d + "/scene.wf", "--json"});
	apps::ModelApp mixed;  // C0 model, left-camera truth, no --head to relate them
	mixed.initialize({"mrolr-model", "stats", d + "/scene.wf", "--truth", d + "/truth_left.wf"});
	std::ostringstream out;
	EXPECT_THROW(mixed.run(out), std::runtime_error);
	apps::ModelApp no_truth;
	EXPECT_THROW(no_truth.initialize({"mrolr-model", "stats", d + "/scene.wf", "--depth",
	                                  d + "/depth_left_mm.png", "--head", kHead}),
	             util::UsageError);
	apps::ModelApp no_left;
	EXPECT_THROW(no_left.initialize({"mrolr-model", "stats", d + "/scene.wf", "--truth",
	                                 d + "/truth_left.wf", "--depth-right",
	                                 d + "/depth_right_mm.png", "--head", kHead}),
	             util::UsageError);
}
