#include <mrolr/apps/RecognizeApp.h>
#include <mrolr/model/WireFrameIO.h>
#include <mrolr/sim/SyntheticScene.h>
#include <mrolr/recog/TransformCluster.h>
#include <mrolr/recog/WireFrameBuilder.h>
#include <mrolr/util/Cli.h>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <sstream>

namespace fs = std::filesystem;
using mrolr::apps::RecognizeApp;

namespace
{
std::string demoDir()
{
	static const std::string dir = []
	{
		// ctest runs each test of this binary in its own process, in parallel: one folder a test
		const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
		const auto d =
		    (fs::temp_directory_path() / ("mrolr_recognize_app_test_" + std::string(info->name())))
		        .string();
		fs::remove_all(d);
		RecognizeApp app;
		app.initialize({"mrolr-recognize", "--make-demo", d});
		std::ostringstream out;
		EXPECT_EQ(app.run(out), 0);
		return d;
	}();
	return dir;
}

nlohmann::json truth()
{
	return nlohmann::json::parse(std::ifstream(demoDir() + "/scenes/truth.json"));
}

int runApp(const std::vector<std::string>& args, std::string& output)
{
	return mrolr::util::runMain("mrolr-recognize",
	                            [&]
	                            {
		                            RecognizeApp app;
		                            app.initialize(args);
		                            std::ostringstream out;
		                            const int rc = app.run(out);
		                            output = out.str();
		                            return rc;
	                            });
}
}  // namespace

// The demo's cube scene: found with the true pose in the JSON; an absent model is "not found";
// the overlay and the 3D scene are written.
TEST(RecognizeApp, JsonPoseMatchesTruthAndFilesWritten)
{
	const auto d = demoDir();
	const auto t = truth()[0];
	ASSERT_EQ(t["target"], "alphabet_cube");
	const auto png = d + "/overlay.png", s3d = d + "/out.3Dscene";
	std::string out;
	ASSERT_EQ(runApp({"mrolr-recognize", "--model", d + "/models/alphabet_cube.wf", "--model",
	                  d + "/models/book.wf", "--scene", d + "/scenes/table_0.wf", "--json",
	                  "--calib", std::string(MROLR_SOURCE_DIR) + "/config/calib_mrpt_bumblebee.ini",
	                  "--overlay", png, "--scene3d", s3d},
	                 out),
	          0);
	const auto j = nlohmann::json::parse(out);
	ASSERT_EQ(j["results"].size(), 2u);
	const auto& cube = j["results"][0];
	EXPECT_TRUE(cube["found"].get<bool>());
	EXPECT_GE(cube["level"].get<int>(), 1);
	Eigen::Matrix4d T, Ttrue;
	for (int r = 0; r < 4; ++r)
		for (int c = 0; c < 4; ++c) T(r, c) = cube["T"][r][c], Ttrue(r, c) = t["T"][r][c];
	EXPECT_LT(mrolr::recog::rotationDistanceDeg(T.block<3, 3>(0, 0), Ttrue.block<3, 3>(0, 0)), 2.0);
	EXPECT_LT((T.block<3, 1>(0, 3) - Ttrue.block<3, 1>(0, 3)).norm(), 5.0);
	EXPECT_FALSE(j["results"][1]["found"].get<bool>());
	EXPECT_GT(fs::file_size(png), 1000u);
	EXPECT_GT(fs::file_size(s3d), 1000u);
}

// Bad arguments exit 2; unreadable inputs exit 1 with the file named.
TEST(RecognizeApp, BadArgumentsAndInputs)
{
	const auto d = demoDir();
	std::string out;
	EXPECT_EQ(runApp({"mrolr-recognize"}, out), 2);
	EXPECT_EQ(runApp({"mrolr-recognize", "--model", d + "/models/cup.wf"}, out), 2);  // no scene
	EXPECT_EQ(runApp({"mrolr-recognize", "--model", "m.wf", "--left", "l.png"}, out), 2);
	EXPECT_EQ(
	    runApp({"mrolr-recognize", "--model", "m.wf", "--scene", "s.wf", "--overlay", "o.png"},
	           out),
	    2);
	EXPECT_EQ(runApp({"mrolr-recognize", "--model", "m.wf", "--scene", "s.wf", "--bogus"}, out), 2);
	EXPECT_EQ(
	    runApp({"mrolr-recognize", "--model", "m.wf", "--scene", "s.wf", "--judgement", "j"}, out),
	    2);  // --judgement draws the image verification: it needs the stereo pair
	EXPECT_EQ(runApp({"mrolr-recognize", "--model", d + "/missing.wf", "--scene",
	                  d + "/scenes/table_0.wf"},
	                 out),
	          1);
	const auto bad = d + "/bad.wf";
	std::ofstream(bad) << "# mrolr wire-frame 1\nunits mm\nframe object\nline 1 0 0 zero 1 0 0\n";
	EXPECT_EQ(runApp({"mrolr-recognize", "--model", bad, "--scene", d + "/scenes/table_0.wf"}, out),
	          1);
	EXPECT_EQ(runApp({"mrolr-recognize", "--model", d + "/models/cup.wf", "--scene",
	                  d + "/scenes/table_0.wf", "--config", d + "/scenes/truth.json"},
	                 out),
	          1);
}

// The stereo path is wired to stereo::reconstructScene: images that do not fit the calibration are
// an error naming the problem, not a crash.
TEST(RecognizeApp, StereoInputsChecked)
{
	const auto d = demoDir();
	std::string out;
	EXPECT_EQ(runApp({"mrolr-recognize", "--model", d + "/models/cup.wf", "--left", d + "/none.png",
	                  "--right", d + "/none.png", "--calib",
	                  std::string(MROLR_SOURCE_DIR) + "/config/calib_mrpt_bumblebee.ini"},
	                 out),
	          1);
}

// An ambiguous answer in --json: "ambiguous": true and every pose with its support, T the best.
TEST(RecognizeApp, JsonReportsAnAmbiguousPoseWithEveryPose)
{
	using V = Eigen::Vector3d;
	const auto dir = fs::temp_directory_path() / "mrolr_recognize_ambiguous";
	fs::create_directories(dir);
	mrolr::recog::WireFrameBuilder label("labelled_box"), plain("plain_box");
	label.box({-60, -30, 0}, {60, 30, 40});
	label.polyline({{60, -20, 8}, {60, 20, 8}, {60, 20, 33}, {60, -20, 33}}, true);
	plain.box({-60, -30, 0}, {60, 30, 40});
	auto scene = mrolr::sim::placeInScene(plain.build(),
	                                        mrolr::sim::tablePose(30, 25, V(20, -80, 700)));
	scene.frame = mrolr::model::WireFrameFrame::LeftCamera;
	mrolr::model::saveWireFrame(label.build(), (dir / "model.wf").string());
	mrolr::model::saveWireFrame(scene, (dir / "scene.wf").string());
	std::string out;
	ASSERT_EQ(runApp({"mrolr-recognize", "--model", (dir / "model.wf").string(), "--scene",
	                  (dir / "scene.wf").string(), "--json"},
	                 out),
	          0)
	    << out;
	const auto r = nlohmann::json::parse(out)["results"][0];
	ASSERT_TRUE(r["found"].get<bool>());
	EXPECT_TRUE(r["ambiguous"].get<bool>());
	ASSERT_GE(r["poses"].size(), 2u);
	EXPECT_EQ(r["poses"][0]["T"], r["T"]);
	for (const auto& p : r["poses"])
	{
		EXPECT_EQ(p["T"].size(), 4u);
		EXPECT_GT(p["support"].get<double>(), 0.0);
	}
	fs::remove_all(dir);
}
