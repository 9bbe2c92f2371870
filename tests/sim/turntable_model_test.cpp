// The simulator's turntable directory feeds `mrolr-model build` directly (issue 6): turntable.ini
// and calib.ini are written in the model's format, and every object of the lab built from the eight
// rendered views meets the issue's targets against its exact wire-frame.
#include <mrolr/apps/ModelApp.h>
#include <mrolr/apps/SimApp.h>
#include <mrolr/stereo/StereoCalibration.h>

#include <mrpt/config/CConfigFile.h>

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include <unistd.h>
#include <sstream>

using namespace mrolr;
namespace fs = std::filesystem;

namespace
{
const std::string kLab = std::string(MROLR_SOURCE_DIR) + "/maps/lab/world.ini";

std::string simTurntable(const std::string& object)
{
	// One folder per test and process: ctest runs the tests of this file in parallel processes,
	// and other build trees may run the same tests at the same time.
	const std::string test = testing::UnitTest::GetInstance()->current_test_info()->name();
	const auto dir = (fs::path(testing::TempDir()) /
	                  ("mrolr_tt_" + object + "_" + test + "_" + std::to_string(::getpid())))
	                     .string();
	fs::remove_all(dir);
	apps::SimApp sim;
	sim.initialize({"mrolr-sim", "--world", kLab, "--turntable", object, "--out", dir, "--json"});
	std::ostringstream out;
	EXPECT_EQ(sim.run(out), 0) << out.str();
	return dir;
}
}  // namespace

TEST(TurntableModel, DirectoryHasModelFormat)
{
	const auto dir = simTurntable("alphabet_cube");
	const auto calib = stereo::loadStereoCalibration(dir + "/calib.ini");
	// the head's ideal cameras: equal intrinsics, the baseline mostly along OpenCV x
	EXPECT_EQ(cv::norm(calib.K_left, calib.K_right), 0.0);
	EXPECT_GT(std::abs(calib.t_LinR_mm[0]), 0.9 * calib.baseline_mm());
	mrpt::config::CConfigFile cfg(dir + "/turntable.ini");
	const int views = cfg.read_int("turntable", "views", 0);
	ASSERT_EQ(views, 8);
	for (int k = 0; k < views; ++k)
	{
		const std::string sec = "view_" + std::to_string(k);
		EXPECT_TRUE(fs::exists(dir + "/" + cfg.read_string(sec, "left", ""))) << sec;
		EXPECT_NEAR(cfg.read_double(sec, "angle_deg", -1), 45.0 * k, 1e-9) << sec;
	}
}

TEST(TurntableModel, AlphabetCubeMeetsIssueTargets)
{
	const auto dir = simTurntable("alphabet_cube");
	apps::ModelApp model;
	model.initialize({"mrolr-model", "build", "--turntable", dir, "--out", dir + "/cube.wf",
	                  "--truth", dir + "/alphabet_cube_truth.wf", "--json"});
	std::ostringstream out;
	ASSERT_EQ(model.run(out), 0) << out.str();
	ASSERT_TRUE(model.quality.has_value());
	EXPECT_GE(model.quality->recovered_fraction, 0.8);
	EXPECT_LT(model.quality->median_endpoint_error_mm, 3.0);
	EXPECT_LE(model.quality->false_features, 3);
}

// With the light rig (disc_grey, backdrop_grey in config/sim.ini), piece stereo, the view support
// test (contours of round bodies dropped) and circles fitted across views, every object of the lab
// meets the issue's targets (docs/model.md lists the figures), with the same options for all.
class LabObject : public testing::TestWithParam<std::string>
{
};

TEST_P(LabObject, MeetsIssueTargets)
{
	const auto dir = simTurntable(GetParam());
	apps::ModelApp model;
	model.initialize({"mrolr-model", "build", "--turntable", dir, "--out", dir + "/m.wf", "--truth",
	                  dir + "/" + GetParam() + "_truth.wf", "--json"});
	std::ostringstream out;
	ASSERT_EQ(model.run(out), 0) << out.str();
	ASSERT_TRUE(model.quality.has_value());
	EXPECT_GE(model.quality->recovered_fraction, 0.8);
	EXPECT_LT(model.quality->median_endpoint_error_mm, 3.0);
	EXPECT_LE(model.quality->false_features, 6);
}

INSTANTIATE_TEST_SUITE_P(TurntableModel, LabObject,
                         testing::Values("bottle", "can", "cup", "drink_package", "hole_punch",
                                         "large_cup", "stapler"));
