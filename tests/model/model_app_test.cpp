#include "SyntheticTurntable.h"

#include <mrolr/apps/ModelApp.h>
#include <mrolr/model/WireFrameIO.h>
#include <mrolr/util/Cli.h>

#include <gtest/gtest.h>
#include <opencv2/imgcodecs.hpp>

#include <filesystem>
#include <sstream>

using mrolr::apps::ModelApp;
using namespace mrolr;

namespace
{
/** A file of this test's own: ctest runs the tests of this binary in parallel processes, so
 * the running test's name keeps them from overwriting each other's files. */
std::string tmp(const std::string& name)
{
	const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
	return ::testing::TempDir() + "model_app_" + info->name() + "_" + name;
}

nlohmann::json runApp(const std::vector<std::string>& args)
{
	ModelApp app;
	app.initialize(args);
	std::ostringstream out;
	EXPECT_EQ(app.run(out), 0);
	return nlohmann::json::parse(out.str());
}

/** Writes a rendered pair, its calibration and its truth; returns nothing (paths fixed). */
void writeSyntheticPair()
{
	model::WireFrame truth;
	const auto faces = model::test::cardsAndDisc(truth);
	const auto rig = stereo::test::testRig();
	cv::Mat L, R;
	stereo::test::renderPair(faces, rig, L, R);
	cv::imwrite(tmp("L.png"), L);
	cv::imwrite(tmp("R.png"), R);
	stereo::saveStereoCalibration(rig, tmp("calib.ini"));
	model::saveWireFrame(truth, tmp("truth.wf"));
}
}  // namespace

TEST(ModelApp, SceneThenStatsShowCliquesEdit)
{
	writeSyntheticPair();
	const auto scene =
	    runApp({"mrolr-model", "scene", "--left", tmp("L.png"), "--right", tmp("R.png"), "--calib",
	            tmp("calib.ini"), "--out", tmp("S.wf"), "--truth", tmp("truth.wf"), "--json"});
	EXPECT_EQ(scene["frame"], "left_camera");
	EXPECT_GE(scene["quality"]["recovered_fraction"].get<double>(), 0.6);
	const auto stats =
	    runApp({"mrolr-model", "stats", tmp("S.wf"), "--truth", tmp("truth.wf"), "--json"});
	EXPECT_DOUBLE_EQ(stats["quality"]["recovered_fraction"].get<double>(),
	                 scene["quality"]["recovered_fraction"].get<double>());
	runApp({"mrolr-model", "show", tmp("S.wf"), "--png", tmp("S.png"), "--scene3d",
	        tmp("S.3Dscene"), "--json"});
	EXPECT_FALSE(cv::imread(tmp("S.png")).empty());
	EXPECT_GT(std::filesystem::file_size(tmp("S.3Dscene")), 100u);
	const auto cl = runApp({"mrolr-model", "cliques", tmp("S.wf"), "--out", tmp("C.wf"), "--json"});
	EXPECT_GT(cl["added_cliques"].get<int>(), 0);
	EXPECT_EQ(model::loadWireFrame(tmp("C.wf")).cliques.size(), cl["cliques"].get<size_t>());
	const auto ed =
	    runApp({"mrolr-model", "edit", tmp("C.wf"), "--out", tmp("E.wf"), "--remove", "1,2",
	            "--add-line", "-10,0,0,10,0,0", "--grasp", "0,0,30,0,0,0", "--json"});
	EXPECT_EQ(ed["removed"].get<int>(), 2);
	const auto e = model::loadWireFrame(tmp("E.wf"));
	EXPECT_TRUE(e.has_grasp);
	EXPECT_EQ(e.lines.back().p1.x(), -10);
}

TEST(ModelApp, SceneInC0WithHeadAngles)
{
	writeSyntheticPair();
	runApp({"mrolr-model", "scene", "--left", tmp("L.png"), "--right", tmp("R.png"), "--calib",
	        tmp("calib.ini"), "--out", tmp("S.wf"), "--json"});
	const auto j =
	    runApp({"mrolr-model", "scene", "--left", tmp("L.png"), "--right", tmp("R.png"), "--calib",
	            tmp("calib.ini"), "--head", "-10,5,0,0", "--out", tmp("S0.wf"), "--json"});
	EXPECT_EQ(j["frame"], "c0");
	const auto L = model::loadWireFrame(tmp("S.wf")), C0 = model::loadWireFrame(tmp("S0.wf"));
	ASSERT_EQ(L.lines.size(), C0.lines.size());
	// a rigid motion keeps lengths
	for (size_t i = 0; i < L.lines.size(); ++i)
		EXPECT_NEAR(L.lines[i].length(), C0.lines[i].length(), 1e-9);
}

TEST(ModelApp, BadArgumentsAreUsageErrors)
{
	for (const std::vector<std::string>& a : {std::vector<std::string>{"mrolr-model", "frobnicate"},
	                                          {"mrolr-model", "scene", "--left", "x"},
	                                          {"mrolr-model", "show", "m.wf"},
	                                          {"mrolr-model", "edit", "m.wf", "--remove", "1,x"},
	                                          {"mrolr-model", "scene", "--left", "l", "--right",
	                                           "r", "--calib", "c", "--out", "o", "--head", "1,2"}})
	{
		ModelApp app;
		EXPECT_THROW(app.initialize(a), util::UsageError) << a[1];
	}
	ModelApp missing;
	missing.initialize({"mrolr-model", "stats", "/nonexistent.wf"});
	std::ostringstream out;
	EXPECT_THROW(missing.run(out), std::runtime_error);
}

TEST(ModelApp, BuildFromTurntableWithCliquesAndStats)
{
	const std::string dir = tmp("turntable");
	model::test::writeTurntableDir(dir);
	const auto j =
	    runApp({"mrolr-model", "build", "--turntable", dir, "--out", tmp("box.wf"), "--json"});
	EXPECT_EQ(j["views"].get<int>(), 8);
	EXPECT_GE(j["quality"]["recovered_fraction"].get<double>(), 0.8);
	EXPECT_LT(j["quality"]["median_endpoint_error_mm"].get<double>(), 3.0);
	const auto wf = model::loadWireFrame(tmp("box.wf"));
	EXPECT_EQ(wf.frame, model::WireFrameFrame::Object);
	EXPECT_GT(wf.cliques.size(), 0u);
}
