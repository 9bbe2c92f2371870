// mrolr-ekf-sim's app class run from arguments: outputs, JSON keys, rawlog, argument errors.
#include <mrolr/apps/EkfSimApp.h>
#include <mrolr/io/TumTrajectory.h>
#include <mrolr/util/Cli.h>

#include <mrpt/obs/CActionRobotMovement2D.h>
#include <mrpt/obs/CObservationBearingRange.h>
#include <mrpt/obs/CRawlog.h>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <sstream>

using mrolr::apps::EkfSimApp;

namespace
{
const std::string kWorld = std::string(MROLR_SOURCE_DIR) + "/maps/lab_points/world.ini";

std::string tempDir(const std::string& name)
{
	const auto d = std::filesystem::temp_directory_path() / ("mrolr_ekf_sim_test_" + name);
	std::filesystem::remove_all(d);
	return d.string();
}
}  // namespace

TEST(EkfSimApp, JsonOutputsAndRawlog)
{
	const std::string dir = tempDir("json");
	EkfSimApp app;
	app.initialize({"mrolr-ekf-sim", "--world", kWorld, "--runs", "3", "--seed", "4", "--out", dir,
	                "--rawlog", dir + "/run0.rawlog", "--json"});
	std::ostringstream out;
	ASSERT_EQ(app.run(out), 0);
	const auto j = nlohmann::json::parse(out.str());
	for (const char* key :
	     {"runs", "steps", "nees_bounds", "nees_inside_fraction", "slam_rms_position_m",
	      "slam_final_position_error_m", "slam_rms_heading_deg", "dr_rms_position_m",
	      "dr_final_position_error_m", "mean_landmark_error_m", "mean_nis", "features_added",
	      "features_deleted", "outliers_rejected", "ms_per_step"})
		EXPECT_TRUE(j.contains(key)) << key;
	EXPECT_EQ(j["runs"], 3);
	EXPECT_EQ(j["nees_bounds"].size(), 2u);
	for (const char* f : {"steps.csv", "nees.csv", "paths.png"})
		EXPECT_TRUE(std::filesystem::file_size(dir + "/" + f) > 100) << f;
	// run 0's paths in the TUM format, on the simulated clock
	const auto& run0 = app.results.front().steps;
	const auto truth = mrolr::io::readTum(dir + "/truth.tum");
	const auto estimate = mrolr::io::readTum(dir + "/estimate.tum");
	ASSERT_EQ(truth.size(), run0.size());
	ASSERT_EQ(estimate.size(), run0.size());
	for (size_t k = 0; k < run0.size(); ++k)
	{
		EXPECT_LT((truth[k].xv_zxphi.head<2>() - run0[k].truth.head<2>()).norm(), 1e-9);
		EXPECT_LT((estimate[k].xv_zxphi.head<2>() - run0[k].estimate.head<2>()).norm(), 1e-9);
		EXPECT_EQ(truth[k].time_s, estimate[k].time_s);
		if (k > 0)
		{
			EXPECT_GT(truth[k].time_s, truth[k - 1].time_s);
		}
	}
	// The rawlog alternates odometry actions and sensory frames with bearing-range observations.
	mrpt::obs::CRawlog rawlog;
	ASSERT_TRUE(rawlog.loadFromRawLogFile(dir + "/run0.rawlog"));
	ASSERT_EQ(rawlog.size(), 2 * app.results.front().steps.size());
	size_t measured = 0;
	for (size_t k = 0; k < app.results.front().steps.size(); ++k)
	{
		const auto acts = rawlog.getAsAction(2 * k);
		ASSERT_TRUE(acts->getActionByClass<mrpt::obs::CActionRobotMovement2D>());
		const auto sf = rawlog.getAsObservations(2 * k + 1);
		const auto obs = sf->getObservationByClass<mrpt::obs::CObservationBearingRange>();
		ASSERT_TRUE(obs);
		measured += obs->sensedData.size();
		for (const auto& m : obs->sensedData) EXPECT_GE(m.landmarkID, 0);
	}
	EXPECT_GT(measured, app.results.front().steps.size() / 2);
}

TEST(EkfSimApp, SameSeedSameResult)
{
	EkfSimApp a, b;
	a.initialize({"x", "--world", kWorld, "--seed", "9", "--json"});
	b.initialize({"x", "--world", kWorld, "--seed", "9", "--json"});
	std::ostringstream oa, ob;
	a.run(oa);
	b.run(ob);
	EXPECT_EQ(a.summary.slam_rms_position_m, b.summary.slam_rms_position_m);
	EXPECT_EQ(a.summary.steps, b.summary.steps);
}

TEST(EkfSimApp, BadArgumentsAreUsageErrors)
{
	EkfSimApp app;
	EXPECT_THROW(app.initialize({"x"}), mrolr::util::UsageError);
	EXPECT_THROW(app.initialize({"x", "--world", kWorld, "--runs", "0"}), mrolr::util::UsageError);
	EXPECT_THROW(app.initialize({"x", "--world", kWorld, "--seed", "-3"}), mrolr::util::UsageError);
}

TEST(EkfSimApp, MalformedWorldLineIsReportedWithItsKey)
{
	const std::string dir = tempDir("badworld");
	std::filesystem::create_directories(dir);
	std::ofstream(dir + "/world.ini") << "[landmarks]\nL1 = 1.0 two 3.0\n[waypoints]\nW0 = 0 0 0\n";
	EkfSimApp app;
	app.initialize({"x", "--world", dir + "/world.ini", "--json"});
	std::ostringstream out;
	try
	{
		app.run(out);
		FAIL() << "malformed world accepted";
	}
	catch (const std::exception& e)
	{
		const std::string what = e.what();
		for (const char* part : {"world.ini", "landmarks", "L1", "two"})
			EXPECT_NE(what.find(part), std::string::npos) << what;
	}
}
