// A mission replayed from its recording alone: the same estimate, decisions, recognised pose and
// grasp; a changed configuration stops at its first divergence; the recorded decisions are for
// reading only; a mission stopped by its bumper replays to the same stop.
#include "MissionTestConfig.h"

#include <mrolr/apps/MissionApp.h>
#include <mrolr/io/ObservationLog.h>
#include <mrolr/util/Cli.h>

#include <mrpt/obs/CObservationRobotPose.h>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <sstream>

using namespace mrolr;
namespace fs = std::filesystem;
using nlohmann::json;

namespace
{
struct AppRun
{
	int code = -1;
	json report;
	std::string out;
};

AppRun runApp(const std::vector<std::string>& args)
{
	apps::MissionApp app;
	app.initialize(args);
	std::ostringstream out, progress;
	AppRun r;
	r.code = app.run(out, progress);
	r.report = app.report;
	r.out = out.str();
	return r;
}

/** A recorded run of the short route, seed 3, in its own folder (ctest runs each test in its own
 * process, in parallel). */
struct Recorded
{
	AppRun run;
	std::string rawlog;
};

Recorded record(const std::string& name)
{
	const auto dir = mission::test::freshTempDir(name);
	return {runApp({"mrolr-mission", "--config", mission::test::configDir() + "/mission_sim.ini",
	                "--set", "plan.route=W0", "--set", "mission.seed=3", "--out", dir, "--quiet"}),
	        dir + "/mission.rawlog"};
}

double largestDifference(const json& a, const json& b)
{
	if (a.is_number() && b.is_number()) return std::abs(a.get<double>() - b.get<double>());
	if (a.is_array() && b.is_array() && a.size() == b.size())
	{
		double m = 0;
		for (size_t i = 0; i < a.size(); ++i) m = std::max(m, largestDifference(a[i], b[i]));
		return m;
	}
	return a == b ? 0 : std::numeric_limits<double>::infinity();
}

json estimates(const json& report)
{
	json out = json::array();
	for (const auto& s : report["robot"]["path"]) out.push_back({s["estimate"], s["P_vv"]});
	return out;
}
}  // namespace

TEST(Replay, ReproducesTheMainMissionFromItsRecordingAlone)
{
	// `make mission`: the shipped configuration, its plan, seed 1
	const auto odir = mission::test::freshTempDir("replay_test_original");
	const Recorded rec{runApp({"mrolr-mission", "--config",
	                           mission::test::configDir() + "/mission_sim.ini", "--out", odir,
	                           "--quiet"}),
	                   odir + "/mission.rawlog"};
	const auto& a = rec.run;
	ASSERT_EQ(a.code, 0) << a.out;
	ASSERT_TRUE(a.report["found"].get<bool>());
	const auto dir = mission::test::freshTempDir("replay_test_replay", false);
	const auto b = runApp({"mrolr-mission", "--replay", rec.rawlog, "--out", dir, "--quiet"});
	EXPECT_EQ(b.code, 0) << b.out;
	EXPECT_TRUE(b.report["replay"]["divergence"].is_null());
	EXPECT_EQ(b.report["replay"]["differences"], json::array()) << b.report["replay"];
	EXPECT_EQ(b.report["replay"]["calls_served"], b.report["replay"]["calls_recorded"]);
	// the estimate's trajectory, with its covariance, to 1e-9
	ASSERT_EQ(a.report["robot"]["path"].size(), b.report["robot"]["path"].size());
	EXPECT_LE(largestDifference(estimates(a.report), estimates(b.report)), 1e-9);
	// the recognised pose and the joint solution, identical
	EXPECT_EQ(a.report["recognition"]["T_OinC0_mm"], b.report["recognition"]["T_OinC0_mm"]);
	EXPECT_EQ(a.report["retrieval"]["joints_d1mm_qdeg"], b.report["retrieval"]["joints_d1mm_qdeg"]);
	EXPECT_EQ(a.report["retrieval"]["T_GinA_mm"], b.report["retrieval"]["T_GinA_mm"]);
	EXPECT_EQ(a.report["retrieval"]["T_OinA_mm"], b.report["retrieval"]["T_OinA_mm"]);
	EXPECT_EQ(a.report["T_OinA"], b.report["T_OinA"]);
	// the recording's figures are reported, and every pair the robot received is in it
	const auto& figures = a.report["recording"];
	EXPECT_EQ(figures["rawlog_bytes"].get<uint64_t>(), fs::file_size(rec.rawlog));
	size_t pairs = 0;
	for (const auto& o : io::readObservationLog(rec.rawlog).observations)
		pairs += o->sensorLabel == "BISIGHT";
	EXPECT_EQ(pairs, a.report["stereo_pairs"].get<size_t>() + a.report["navigation_pairs"].get<size_t>());
	EXPECT_GE(figures["images"].get<size_t>(), 2 * pairs);
	EXPECT_GT(figures["writer_seconds"].get<double>(), 0.0);
	for (const char* k : {"success", "failure", "found", "retrieved", "returned_home", "stopped",
	                      "stages", "found_at_station", "measurements", "navigation_pairs"})
		EXPECT_EQ(a.report[k], b.report[k]) << k;
	// eval rechecks the replay with the recording's truth: the same figures
	EXPECT_EQ(a.report["object_translation_error_mm"], b.report["object_translation_error_mm"]);
	EXPECT_EQ(a.report["final_position_error_m"], b.report["final_position_error_m"]);
	// and replaying again gives the same results to the bit
	const auto again = runApp({"mrolr-mission", "--replay", rec.rawlog, "--out",
	                           mission::test::freshTempDir("replay_test_again", false), "--quiet"});
	EXPECT_EQ(estimates(again.report), estimates(b.report));
	EXPECT_EQ(again.report["retrieval"]["joints_d1mm_qdeg"], b.report["retrieval"]["joints_d1mm_qdeg"]);
}

TEST(Replay, AChangedConfigurationThatLooksElsewhereStopsAtTheFirstDivergenceAndNamesIt)
{
	const auto rec = record("replay_test_original_diverged");
	ASSERT_EQ(rec.run.code, 0);
	// the fixed pans instead of the pans that cover the table: the sweep asks for other angles
	const auto b = runApp({"mrolr-mission", "--replay", rec.rawlog, "--set",
	                       "search.cover_table=false", "--out",
	                       mission::test::freshTempDir("replay_test_diverged", false), "--quiet"});
	EXPECT_EQ(b.code, 3);
	const std::string d = b.report["replay"]["divergence"].get<std::string>();
	EXPECT_NE(d.find("in stage search: replay diverged at device call"), std::string::npos) << d;
	EXPECT_NE(d.find("the robot asked head.moveTo("), std::string::npos) << d;
	EXPECT_NE(d.find("where the recording has head.moveTo("), std::string::npos) << d;
	EXPECT_TRUE(b.report["stopped"].get<bool>());
	EXPECT_NE(b.report["failure"].get<std::string>().find(d), std::string::npos);
	EXPECT_FALSE(b.report["success"].get<bool>()) << "it never invents the rest of the run";
	EXPECT_LT(b.report["replay"]["calls_served"].get<int>(),
	          b.report["replay"]["calls_recorded"].get<int>());
}

TEST(Replay, CorruptedDecisionsInTheRecordingDoNotChangeTheReplay)
{
	const auto rec = record("replay_test_original_corrupted");
	ASSERT_EQ(rec.run.code, 0);
	// a copy of the run whose recorded estimates are 1 m off and whose recorded recognition
	// names another object: the replay never reads them
	const auto dir = mission::test::freshTempDir("replay_test_corrupted");
	const fs::path from = fs::path(rec.rawlog).parent_path();
	fs::copy(from, dir, fs::copy_options::recursive | fs::copy_options::overwrite_existing);
	fs::remove_all(fs::path(dir) / "replay");
	auto log = io::readObservationLog(rec.rawlog);
	{
		io::ObservationLogWriter w(dir + "/mission.rawlog");
		int corrupted = 0;
		for (auto& obs : log.observations)
		{
			if (auto p = std::dynamic_pointer_cast<mrpt::obs::CObservationRobotPose>(obs);
			    p && p->sensorLabel == "ESTIMATE")
				p->pose.mean.x_incr(1.0), ++corrupted;
			if (auto c = std::dynamic_pointer_cast<mrpt::obs::CObservationComment>(obs);
			    c && c->sensorLabel == "RECOGNISED")
			{
				w.write(*io::labelledComment("RECOGNISED", "bottle, somewhere else", c->timestamp));
				++corrupted;
				continue;
			}
			if (auto c = std::dynamic_pointer_cast<mrpt::obs::CObservationComment>(obs))
			{
				w.write(*io::labelledComment(c->sensorLabel, c->text, c->timestamp));
				continue;
			}
			w.write(*obs);
		}
		ASSERT_GT(corrupted, 10);
	}
	const auto b = runApp({"mrolr-mission", "--replay", dir + "/mission.rawlog", "--quiet"});
	EXPECT_EQ(b.code, 0) << b.out;
	EXPECT_EQ(b.report["replay"]["differences"], json::array()) << b.report["replay"];
	EXPECT_EQ(estimates(b.report), estimates(rec.run.report));
	EXPECT_EQ(b.report["recognition"]["T_OinC0_mm"], rec.run.report["recognition"]["T_OinC0_mm"]);
}

TEST(Replay, AMissionStoppedByItsBumperReplaysToTheSameStopWithTheSameReason)
{
	// the plan has no table, and its route runs straight through the lab's (honest_run_test)
	const auto dir = mission::test::freshTempDir("replay_test_bumper");
	std::ofstream(dir + "/plan.ini") << "[plan]\nroute = W0 T\nstations = W5\nhome = W6\n"
	                                    "[waypoints]\nW0 = 0 0 0\nT = 2.4 0 0\nW5 = 0.5 0 0\n"
	                                    "W6 = 0 0 0\n";
	const auto a = runApp({"mrolr-mission", "--config", mission::test::configDir() + "/mission_sim.ini",
	                       "--plan", dir + "/plan.ini", "--set", "mission.obstacle_mode=false",
	                       "--out", dir + "/run", "--quiet"});
	ASSERT_TRUE(a.report["robot"]["collided"].get<bool>()) << a.out;
	const auto b = runApp({"mrolr-mission", "--replay", dir + "/run/mission.rawlog", "--quiet"});
	EXPECT_EQ(b.code, 0) << b.out;
	EXPECT_TRUE(b.report["robot"]["collided"].get<bool>());
	EXPECT_EQ(b.report["failure"], a.report["failure"]);
	EXPECT_EQ(b.report["robot"]["collision_estimate_zxphi"], a.report["robot"]["collision_estimate_zxphi"]);
	EXPECT_TRUE(b.report["replay"]["divergence"].is_null()) << b.report["replay"];
}

TEST(Replay, BadArgumentsAndMissingRecordingsAreNamed)
{
	EXPECT_THROW(runApp({"mrolr-mission", "--replay", "/nonexistent/mission.rawlog"}), std::exception);
	try
	{
		runApp({"mrolr-mission", "--replay", "/nonexistent/mission.rawlog"});
	}
	catch (const std::exception& e)
	{
		EXPECT_NE(std::string(e.what()).find("/nonexistent/mission.rawlog"), std::string::npos);
	}
	apps::MissionApp app;
	EXPECT_THROW(app.initialize({"mrolr-mission", "--replay", "x.rawlog", "--world", "w.ini"}),
	             util::UsageError);
	// a recording without its run's configuration beside it needs --config
	const auto dir = mission::test::freshTempDir("replay_test_noconfig");
	std::ofstream(dir + "/mission.rawlog") << "";
	try
	{
		runApp({"mrolr-mission", "--replay", dir + "/mission.rawlog"});
		ADD_FAILURE() << "ran without a configuration";
	}
	catch (const std::exception& e)
	{
		EXPECT_NE(std::string(e.what()).find("--config"), std::string::npos) << e.what();
	}
}
