// The robot in its own process: the emulator (mrolr-serial emulate) serves the lab's devices on
// pseudo-terminals and its camera on a socket, the world's files are then taken away, and the
// robot side runs the mission from the hardware configuration, its plan and its models; eval
// checks it from the emulator's T.json. And Ctrl-C (SIGINT) stops a running mission safely with
// every output written.
#include "ChildProcess.h"
#include "MissionTestConfig.h"

#include <mrolr/apps/EvalApp.h>
#include <mrolr/apps/MissionApp.h>
#include <mrolr/io/ObservationLog.h>
#include <mrolr/io/Rawlog.h>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <sstream>

using namespace mrolr;
namespace fs = std::filesystem;

namespace
{
const std::string kBin = MROLR_BIN_DIR;
const std::string kRoot = MROLR_SOURCE_DIR;

/** The report of `mrolr-mission --replay RAWLOG` (its outputs beside the recording). */
nlohmann::json replay(const std::string& rawlog)
{
	apps::MissionApp app;
	app.initialize({"mrolr-mission", "--replay", rawlog, "--quiet"});
	std::ostringstream out, progress;
	app.run(out, progress);
	return app.report;
}

size_t countLabel(const std::string& rawlog, const std::string& label)
{
	size_t n = 0;
	for (const auto& o : io::readObservationLog(rawlog).observations) n += o->sensorLabel == label;
	return n;
}

/** The second word of a "name value" line. */
std::string valueOf(const std::string& line, const std::string& name)
{
	std::istringstream s(line);
	std::string n, v;
	s >> n >> v;
	if (n != name) throw std::runtime_error("expected '" + name + " ...', got '" + line + "'");
	return v;
}

/** Every world and object definition under @p dir removed: the robot side must not need them. */
int removeWorldFiles(const std::string& dir)
{
	int n = 0;
	for (const auto& e : fs::recursive_directory_iterator(dir))
		if (e.path().filename() == "world.ini" ||
		    (e.path().extension() == ".ini" && e.path().parent_path().filename() == "objects"))
			fs::remove(e.path()), ++n;
	return n;
}
}  // namespace

TEST(TwoProcesses, TheRobotRunsWithoutTheWorldsFilesAndEvalChecksItFromTJson)
{
	const auto tmp = mission::test::freshTempDir("process_test_two");
	fs::create_directories(tmp + "/maps");
	fs::create_directories(tmp + "/datasets");
	fs::copy(kRoot + "/maps/lab", tmp + "/maps/lab", fs::copy_options::recursive);
	fs::copy(kRoot + "/datasets/objects", tmp + "/datasets/objects", fs::copy_options::recursive);
	test::ChildProcess emulator({kBin + "/mrolr-serial", "emulate", "--sim",
	                             kRoot + "/config/mission_sim.ini", "--world",
	                             tmp + "/maps/lab/world.ini", "--truth-out", tmp + "/T.json"});
	const auto base = valueOf(emulator.readLine(30), "base");
	const auto head = valueOf(emulator.readLine(5), "head");
	const auto arm = valueOf(emulator.readLine(5), "arm");
	const auto camera = valueOf(emulator.readLine(5), "camera");
	EXPECT_GT(removeWorldFiles(tmp), 8);  // the world and its eight object definitions
	ASSERT_FALSE(fs::exists(tmp + "/maps/lab/world.ini"));

	apps::MissionApp app;
	app.initialize({"mrolr-mission", "--config", kRoot + "/config/mission_hw.ini", "--plan",
	                tmp + "/maps/lab/plan.ini", "--set", "files.models_dir=" + tmp + "/datasets/objects",
	                "--set", "plan.route=W0", "--set", "device.base.port=" + base, "--set",
	                "device.head.port=" + head, "--set", "device.arm.port=" + arm, "--set",
	                "device.camera.driver=socket", "--set", "device.camera.address=" + camera,
	                "--out", tmp + "/out", "--quiet"});
	std::ostringstream out, progress;
	EXPECT_EQ(app.run(out, progress), 0) << out.str();
	EXPECT_TRUE(app.report["eval"].is_null());  // no truth in the robot's process
	EXPECT_EQ(app.result.links.size(), 3u);
	emulator.signal(SIGINT);
	EXPECT_EQ(emulator.wait(20), 0);
	ASSERT_TRUE(fs::exists(tmp + "/T.json"));
	// the truth of every step is the emulator's, beside T.json; the robot's recording has none
	EXPECT_GE(countLabel(tmp + "/T.rawlog", "GROUND_TRUTH"), app.result.path.size());
	EXPECT_EQ(countLabel(tmp + "/out/mission.rawlog", "GROUND_TRUTH"), 0u);
	EXPECT_GT(countLabel(tmp + "/out/mission.rawlog", "BASE_ODOMETRY"), 0u);

	apps::EvalApp eval;
	eval.initialize({"mrolr-eval", "--report", tmp + "/out/report.json", "--truth", tmp + "/T.json"});
	std::ostringstream eval_out;
	EXPECT_EQ(eval.run(eval_out), 0) << eval_out.str();
	const auto T = nlohmann::json::parse(std::ifstream(tmp + "/T.json"));
	const Eigen::Vector2d home = app.options.plan.home.xv_zxphi.head<2>();
	EXPECT_LT(std::hypot(T["vehicle"]["z_m"].get<double>() - home.x(),
	                     T["vehicle"]["x_m"].get<double>() - home.y()),
	          0.15);
	EXPECT_EQ(T["on_board"], nlohmann::json::array({app.options.target}));  // rode home on the deck
	EXPECT_TRUE(eval.report["eval"]["confirms"].get<bool>());
	EXPECT_TRUE(eval.report["success"].get<bool>());
}

TEST(TwoProcesses, ADeadCameraSocketStopsTheMissionSafelyNamingIt)
{
	const auto tmp = mission::test::freshTempDir("process_test_dead_camera");
	test::ChildProcess emulator({kBin + "/mrolr-serial", "emulate", "--sim",
	                             kRoot + "/config/mission_sim.ini"});
	const auto base = valueOf(emulator.readLine(30), "base");
	const auto head = valueOf(emulator.readLine(5), "head");
	const auto arm = valueOf(emulator.readLine(5), "arm");
	const auto camera = valueOf(emulator.readLine(5), "camera");
	apps::MissionApp app;
	app.initialize({"mrolr-mission", "--config", kRoot + "/config/mission_hw.ini", "--set",
	                "device.base.port=" + base, "--set",
	                "device.head.port=" + head, "--set", "device.arm.port=" + arm, "--set",
	                "device.camera.driver=socket", "--set", "device.camera.address=" + camera,
	                "--set", "device.camera.timeout_ms=1000", "--out", tmp + "/out", "--quiet"});
	std::thread killer([&] {
		std::this_thread::sleep_for(std::chrono::seconds(3));
		emulator.signal(SIGKILL);  // the whole emulator dies: ports and camera
	});
	std::ostringstream out, progress;
	EXPECT_EQ(app.run(out, progress), 3) << out.str();
	killer.join();
	EXPECT_TRUE(app.result.stopped);
	EXPECT_NE(app.result.failure.find("device."), std::string::npos) << app.result.failure;
	EXPECT_TRUE(fs::exists(tmp + "/out/report.json"));
	// the recording replays up to the fault and stops there, for the same reason
	const auto replayed = replay(tmp + "/out/mission.rawlog");
	EXPECT_TRUE(replayed["stopped"].get<bool>());
	EXPECT_EQ(replayed["failure"].get<std::string>(), app.result.failure);
	EXPECT_TRUE(replayed["replay"]["divergence"].is_null()) << replayed["replay"];
}

TEST(Interrupt, SigintStopsARunningMissionSafelyWithEveryOutputWritten)
{
	const auto tmp = mission::test::freshTempDir("process_test_sigint");
	test::ChildProcess mission({kBin + "/mrolr-mission", "--config",
	                            kRoot + "/config/mission_sim.ini", "--out", tmp + "/out",
	                            "--quiet"});
	std::this_thread::sleep_for(std::chrono::seconds(4));
	mission.signal(SIGINT);
	EXPECT_EQ(mission.wait(60), 130);
	const auto j = nlohmann::json::parse(std::ifstream(tmp + "/out/report.json"));
	EXPECT_TRUE(j["interrupted"].get<bool>());
	EXPECT_TRUE(j["stopped"].get<bool>());
	EXPECT_FALSE(j["success"].get<bool>());
	EXPECT_NE(j["failure"].get<std::string>().find("SIGINT"), std::string::npos);
	bool base_stopped = false;
	for (const auto& e : j["timeline"]) base_stopped |= e["event"] == "base stopped";
	EXPECT_TRUE(base_stopped);
	for (const char* f : {"report.md", "trajectory.png", "mission.3Dscene"})
		EXPECT_TRUE(fs::exists(tmp + "/out/" + f)) << f;
	// every pair the robot saw is in the recording, and the stop replays at the same call
	EXPECT_EQ(countLabel(tmp + "/out/mission.rawlog", "BISIGHT"),
	          j["stereo_pairs"].get<size_t>() + j["navigation_pairs"].get<size_t>());
	const auto replayed = replay(tmp + "/out/mission.rawlog");
	EXPECT_TRUE(replayed["interrupted"].get<bool>());
	EXPECT_EQ(replayed["failure"], j["failure"]);
	EXPECT_EQ(replayed["robot"]["final_estimate_zxphi"], j["robot"]["final_estimate_zxphi"]);
	EXPECT_EQ(replayed["replay"]["differences"], nlohmann::json::array()) << replayed["replay"];
}

TEST(Recording, AMissionKilledMidRunLeavesARawlogReadableUpToItsLastRecord)
{
	const auto tmp = mission::test::freshTempDir("process_test_sigkill");
	const auto rawlog = tmp + "/out/mission.rawlog";
	test::ChildProcess mission({kBin + "/mrolr-mission", "--config",
	                            kRoot + "/config/mission_sim.ini", "--out", tmp + "/out",
	                            "--quiet"});
	// killed while it drives, once it has recorded some stereo pairs
	const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
	while ((!fs::exists(rawlog) || fs::file_size(rawlog) < 100000) &&
	       std::chrono::steady_clock::now() < deadline)
		std::this_thread::sleep_for(std::chrono::milliseconds(20));
	mission.signal(SIGKILL);
	mission.wait(30);
	ASSERT_GE(fs::file_size(rawlog), 100000u);
	EXPECT_FALSE(fs::exists(tmp + "/out/report.json")) << "killed before its end";
	const auto log = io::readObservationLog(rawlog);
	EXPECT_GT(log.observations.size(), 100u);
	// read as records too: odometry readings and stereo pairs, each pair with its images
	const auto records = io::readRawlog(rawlog);
	size_t pairs = 0;
	for (const auto& r : records) pairs += r.has_stereo && r.left.getWidth() == 640;
	EXPECT_EQ(pairs, countLabel(rawlog, "HEAD_GRAB"));
	EXPECT_GT(pairs, 10u);
	// MRPT's own tool reads it too, to the same last record
	const std::string info = tmp + "/info.txt";
	ASSERT_EQ(std::system(("rawlog-edit --info -i " + rawlog + " > " + info + " 2>&1").c_str()), 0);
	std::stringstream s;
	s << std::ifstream(info).rdbuf();
	EXPECT_NE(s.str().find("Overall number of objects         : " +
	                       std::to_string(log.observations.size())),
	          std::string::npos)
	    << s.str();
	// and the replay runs up to there and says where the recording ends
	const auto replayed = replay(rawlog);
	EXPECT_NE(replayed["replay"]["divergence"].get<std::string>().find("after the recording's last call"),
	          std::string::npos);
}

TEST(MissionProcess, ProgressToAFileIsPlainLinesNotOneRewrittenLine)
{
	const auto dir = mission::test::freshTempDir("process_progress_to_file");
	const std::string cmd = "cd " + kRoot + " && " + kBin + "/mrolr-mission --set plan.route=W0 --out " +
	                        dir + "/out > /dev/null 2> " + dir + "/progress.txt";
	ASSERT_EQ(std::system(cmd.c_str()), 0) << cmd;
	std::ifstream f(dir + "/progress.txt");
	const std::string text((std::istreambuf_iterator<char>(f)), {});
	EXPECT_EQ(text.find('\r'), std::string::npos);
	std::istringstream lines(text);
	size_t n = 0;
	for (std::string line; std::getline(lines, line);)
		if (!line.empty())
		{
			EXPECT_EQ(line.rfind("[mission] ", 0), 0u) << line;
			EXPECT_LT(line.size(), 120u) << line;
			++n;
		}
	const auto report = nlohmann::json::parse(std::ifstream(dir + "/out/report.json"));
	EXPECT_GE(n, 2u);                                  // a line per stage at least
	EXPECT_LT(n, report["robot"]["path"].size() / 2);  // not one per step
}
