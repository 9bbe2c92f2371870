#include <mrolr/apps/RecognizeApp.h>
#include <mrolr/model/WireFrameIO.h>
#include <mrolr/util/Cli.h>
#include <mrolr/util/Config.h>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <opencv2/imgcodecs.hpp>

#include <filesystem>
#include <fstream>
#include <sstream>

namespace fs = std::filesystem;
using mrolr::apps::RecognizeApp;

// The shipped 12-scene set as mrolr-recognize --evaluate runs it (every lab model in every
// scene, with the scene's up direction, its support plane, its stereo pair for verification in
// the images and the second search behind the objects found). The claims of docs/recog.md over
// the set: no model absent from a scene is reported found, at least 90 % of the present ones are
// recognised, and the median pose errors are within the thesis's 2° and 5 mm.
TEST(RenderedEval, ShippedSetHasNoFalsePositiveAndRecognisesNinetyPercent)
{
	const auto dir = (fs::temp_directory_path() / "mrolr_rendered_eval_rate_test").string();
	fs::remove_all(dir);
	RecognizeApp app;
	app.initialize({"mrolr-recognize", "--evaluate", dir});
	std::ostringstream out;
	ASSERT_EQ(app.run(out), 0);
	const mrolr::eval::EvalSummary& s = app.eval_summary;
	ASSERT_GT(s.rate_cases, 0);
	EXPECT_GT(s.absent_cases, 0);
	EXPECT_EQ(s.false_positives, 0);
	EXPECT_GE(s.recognised, 0.9 * s.rate_cases);
	EXPECT_LT(s.median_rot_err_deg, 2.0);
	EXPECT_LT(s.median_trans_err_mm, 5.0);
	int behind_found = 0;
	for (const auto& c : app.eval_cases) behind_found += c.result.occluders > 0 ? 1 : 0;
	RecordProperty("rate_cases", s.rate_cases);
	RecordProperty("recognised", s.recognised);
	RecordProperty("wrong_poses", s.wrong_poses);
	std::printf("recognised %d/%d, false positives %d/%d, wrong poses %d, %d behind found\n",
	            s.recognised, s.rate_cases, s.false_positives, s.absent_cases, s.wrong_poses,
	            behind_found);
	fs::remove_all(dir);
}

// mrolr-recognize --evaluate writes the scenes, their overlays and the summary.
TEST(RenderedEval, AppWritesOverlayAndSummary)
{
	const auto dir = (fs::temp_directory_path() / "mrolr_rendered_eval_test").string();
	fs::remove_all(dir);
	RecognizeApp app;
	app.initialize({"mrolr-recognize", "--evaluate", dir, "--eval-scenes", "1", "--model",
	                mrolr::util::requireProjectFile("datasets/objects/drink_package.wf")});
	std::ostringstream out;
	ASSERT_EQ(app.run(out), 0);
	const cv::Mat overlay = cv::imread(dir + "/scene_00/overlay.png");
	EXPECT_EQ(overlay.cols, 640);
	EXPECT_EQ(overlay.rows, 480);
	const auto summary = nlohmann::json::parse(std::ifstream(dir + "/summary.json"));
	EXPECT_EQ(summary["rate_cases"].get<int>() + summary["absent_cases"].get<int>() >= 0, true);
	EXPECT_EQ(app.eval_cases.size(), 1u);
	EXPECT_TRUE(fs::exists(dir + "/scene_00/scene.wf"));
	EXPECT_NE(out.str().find("false positives"), std::string::npos);
}

// --evaluate renders its own scenes: a scene argument beside it is a usage error.
TEST(RenderedEval, EvaluateWithASceneIsAUsageError)
{
	RecognizeApp app;
	EXPECT_THROW(app.initialize({"mrolr-recognize", "--evaluate", "/tmp/x", "--scene", "s.wf"}),
	             mrolr::util::UsageError);
	EXPECT_THROW(app.initialize({"mrolr-recognize", "--evaluate", "/tmp/x", "--eval-scenes", "-3"}),
	             mrolr::util::UsageError);
}

// --support-plane nx,ny,nz,d_mm: normalised; three numbers, a zero normal or a scene file instead
// of a stereo pair are usage errors.
TEST(RenderedEval, SupportPlaneArgument)
{
	const std::vector<std::string> stereo = {"mrolr-recognize", "--model", "m.wf",
	                                         "--left",          "l.png",   "--right",
	                                         "r.png",           "--calib", "c.ini"};
	auto with = [&](std::vector<std::string> extra)
	{
		auto a = stereo;
		a.insert(a.end(), extra.begin(), extra.end());
		return a;
	};
	RecognizeApp app;
	app.initialize(with({"--support-plane", "0,2,0,300"}));
	ASSERT_TRUE(app.support_plane.has_value());
	EXPECT_NEAR(app.support_plane->n_S.y(), 1.0, 1e-12);
	EXPECT_NEAR(app.support_plane->d_mm, 150.0, 1e-12);
	EXPECT_TRUE(app.plane_hypotheses);
	RecognizeApp off;
	off.initialize(with({"--support-plane", "0,1,0,0", "--no-plane-hypotheses"}));
	EXPECT_FALSE(off.plane_hypotheses);
	for (const auto& bad : {"0,1,0", "0,0,0,5", "a,1,0,0"})
	{
		RecognizeApp b;
		EXPECT_THROW(b.initialize(with({"--support-plane", bad})), mrolr::util::UsageError) << bad;
	}
	RecognizeApp s;
	EXPECT_THROW(s.initialize({"mrolr-recognize", "--model", "m.wf", "--scene", "s.wf",
	                           "--support-plane", "0,1,0,0"}),
	             mrolr::util::UsageError);
}

// mrolr-recognize --judgement draws, for a model found in a rendered pair, its judged samples on
// the left image: the supported ones green.
TEST(RenderedEval, JudgementDrawsTheSupportedSamples)
{
	const auto dir = (fs::temp_directory_path() / "mrolr_rendered_eval_judgement_test").string();
	fs::remove_all(dir);
	RecognizeApp eval;
	eval.initialize({"mrolr-recognize", "--evaluate", dir, "--eval-scenes", "1"});
	std::ostringstream eval_out;
	ASSERT_EQ(eval.run(eval_out), 0);
	const mrolr::eval::EvalCase* found = nullptr;
	for (const auto& c : eval.eval_cases)
		if (c.correct) found = &c;
	ASSERT_NE(found, nullptr) << "nothing recognised in scene 0";
	const auto truth = nlohmann::json::parse(std::ifstream(dir + "/scene_00/truth.json"));
	std::ostringstream plane;
	for (const double v : truth["support_plane_L"]) plane << (plane.tellp() ? "," : " ") << v;
	const std::string s = dir + "/scene_00/", prefix = dir + "/judged";
	RecognizeApp app;
	app.initialize({"mrolr-recognize", "--model",
	                mrolr::util::requireProjectFile("datasets/objects/" + found->model + ".wf"),
	                "--left", s + "left.png", "--right", s + "right.png", "--calib",
	                s + "calib.ini", "--support-plane", plane.str(), "--judgement", prefix});
	std::ostringstream out;
	ASSERT_EQ(app.run(out), 0);
	ASSERT_TRUE(app.results.at(0).found) << out.str();
	const cv::Mat img = cv::imread(prefix + "_" + found->model + ".png", cv::IMREAD_COLOR);
	ASSERT_EQ(img.cols, 640);
	ASSERT_EQ(img.rows, 480);
	int green = 0;
	for (int y = 0; y < img.rows; ++y)
		for (int x = 0; x < img.cols; ++x)
		{
			const cv::Vec3b p = img.at<cv::Vec3b>(y, x);
			green += p[1] > 150 && p[0] < 100 && p[2] < 100 ? 1 : 0;
		}
	EXPECT_GT(green, 30);
	fs::remove_all(dir);
}
