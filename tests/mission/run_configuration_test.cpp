// The run's effective configuration is kept with its outputs (<out>/run/): the mission file with
// every --set written in, copies of the files it names and of the model database, the plan as
// used and the command; running that file again reproduces the run exactly, from any folder.
#include "MissionTestConfig.h"

#include <mrolr/apps/MissionApp.h>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <sstream>

using namespace mrolr;
namespace fs = std::filesystem;

namespace
{
nlohmann::json runApp(const std::vector<std::string>& args)
{
	apps::MissionApp app;
	app.initialize(args);
	std::ostringstream out, progress;
	EXPECT_EQ(app.run(out, progress), 0) << out.str();
	return app.report;
}

std::string text(const fs::path& p)
{
	std::ifstream f(p);
	std::stringstream s;
	s << f.rdbuf();
	return s.str();
}
}  // namespace

TEST(RunConfiguration, IsKeptWithTheOutputsAndRunsTheSameMissionAgain)
{
	const auto first = mission::test::freshTempDir("run_configuration_test_first");
	const auto again = mission::test::freshTempDir("run_configuration_test_again");
	const auto a = runApp({"mrolr-mission", "--config", mission::test::configDir() + "/mission_sim.ini",
	                       "--set", "plan.route=W0", "--set", "mission.seed=3", "--out", first,
	                       "--quiet"});
	const fs::path run = fs::path(first) / "run";
	// every file the mission named is copied beside its mission file, which names the copies
	for (const char* f : {"labmate.ini", "bisight.ini", "arm_rtx.ini", "recognition.ini",
	                      "plan/plan.ini", "models/alphabet_cube.wf", "command.txt"})
		EXPECT_TRUE(fs::exists(run / f)) << f;
	const std::string ini = text(run / "mission.ini");
	EXPECT_NE(ini.find("labmate_file = labmate.ini"), std::string::npos);
	EXPECT_NE(ini.find("models_dir = models"), std::string::npos);
	EXPECT_NE(ini.find("seed = 3"), std::string::npos) << "the --set is written in";
	EXPECT_NE(text(run / "plan/plan.ini").find("route = W0"), std::string::npos)
	    << "the plan as used, its override applied";
	EXPECT_NE(text(run / "command.txt").find("mission.seed=3"), std::string::npos);
	// run again from that file alone, from another working directory
	const auto cwd = fs::current_path();
	fs::current_path(fs::temp_directory_path());
	const auto b = runApp({"mrolr-mission", "--config", (run / "mission.ini").string(), "--out",
	                       again, "--quiet"});
	fs::current_path(cwd);
	EXPECT_EQ(a["robot"]["final_estimate_zxphi"], b["robot"]["final_estimate_zxphi"]);
	EXPECT_EQ(a["robot"]["path"], b["robot"]["path"]);
	EXPECT_EQ(a["retrieval"]["T_GinA_mm"], b["retrieval"]["T_GinA_mm"]);
	EXPECT_EQ(a["success"], b["success"]);
}
