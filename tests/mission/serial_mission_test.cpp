// The whole mission through real serial I/O: the simulated lab's base, head and arm are served on
// pseudo-terminals (apps::SerialEmulation), the mission drives them with the serial drivers
// (driver = serial), with faults injected; and devices that stop answering, refuse or send garbage.
#include "MissionTestConfig.h"

#include <mrolr/apps/MissionApp.h>
#include <mrolr/apps/SerialEmulation.h>
#include <mrolr/eval/MissionOutputs.h>
#include <mrolr/io/Rawlog.h>
#include <mrolr/mission/DeviceRecorder.h>
#include <mrolr/mission/Mission.h>
#include <mrolr/mission/MissionOutputs.h>
#include <mrolr/util/Cli.h>
#include <mrolr/util/Config.h>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>

using namespace mrolr;
using namespace mrolr::mission;
namespace fs = std::filesystem;

namespace
{
/** Short link timeouts, so that a device that stops answering is given up within a second. */
hw_serial::LinkOptions quickLinks()
{
	hw_serial::LinkOptions l;
	l.timeout_ms = 100;
	l.motion_timeout_ms = 300;
	l.retries = 2;
	return l;
}

/** A mission (the short route) on a simulated lab served on ptys; faults can be set before
 * run(). The camera is the lab's own (in process). */
struct SerialRig
{
	mrpt::config::CConfigFileMemory cfg = test::defaultMissionConfig();
	MissionOptions o = test::optionsFrom(cfg, test::shortRoute());
	std::unique_ptr<sim::Lab> lab;
	std::unique_ptr<apps::SerialEmulation> emulation;
	std::unique_ptr<MissionDevices> devices;
	std::unique_ptr<Mission> mission;
	explicit SerialRig(const hw_serial::FaultOptions& faults = {},
	                   const hw_serial::LinkOptions& links = quickLinks(),
	                   const std::function<void(sim::LabOptions&)>& world = {})
	{
		auto lo = sim::LabOptions::load(cfg, test::configDir());
		if (world) world(lo);
		lab = std::make_unique<sim::Lab>(lo);
		emulation = std::make_unique<apps::SerialEmulation>(*lab, faults);
		emulation->useIn(o, links);
		devices = std::make_unique<MissionDevices>(o.devices, SimDevices{nullptr, &lab->head(), nullptr});
		mission = std::make_unique<Mission>(o, devices->devices());  // connected: ID? on every port
	}
	/** The mission run with its recording in @p dir/mission.rawlog, as mrolr-mission runs it. */
	MissionResult runRecorded(const std::string& dir)
	{
		DeviceRecorder recorder(dir + "/mission.rawlog", devices->devices(),
		                        geometry::BiSightHead(o.bisight));
		auto r = Mission(o, recorder.devices()).run();
		recorder.flush();
		return r;
	}
	nlohmann::json report(const MissionResult& r) const
	{
		auto j = reportJson(r, o);
		eval::evaluateMission(j, eval::truthOf(*lab));
		return j;
	}
};

int totalResends(const MissionResult& r)
{
	int n = 0;
	for (const auto& l : r.links) n += l.resends;
	return n;
}

void expectSamePaths(const MissionResult& a, const MissionResult& b)
{
	ASSERT_EQ(a.path.size(), b.path.size());
	for (size_t i = 0; i < a.path.size(); ++i)
	{
		EXPECT_EQ(a.path[i].odometry, b.path[i].odometry) << i;
		EXPECT_EQ(a.path[i].estimate, b.path[i].estimate) << i;
	}
}
}  // namespace

TEST(SerialMission, ThroughPtysWithDelaysAndLostBytesItIsTheSimulatedMission)
{
	const auto sim = test::runMission(test::defaultMissionConfig(), test::shortRoute());
	hw_serial::FaultOptions faults;
	faults.reply_delay_ms = 1;
	faults.drop_byte_probability = 0.002;
	faults.seed = 5;
	// The seeded drops fall on the same bytes only while the byte flow is the same; on a loaded
	// machine a slow reply is resent, the flow shifts, and with 2 retries one command of the
	// mission's hundreds lost all three replies once (a ~60-byte reply is hit with p ~ 0.11, three
	// in a row ~ 1e-3). With 4 retries that is ~ 2e-5 per command.
	auto links = quickLinks();
	links.retries = 4;
	SerialRig rig(faults, links);
	const auto serial = rig.mission->run();
	EXPECT_TRUE(serial.success) << serial.failure;
	EXPECT_EQ(serial.success, sim.r.success);
	EXPECT_EQ(serial.retrieved, sim.r.retrieved);
	// Numbers cross the line exactly (shortest round-trip text), and a resent STEP or MOVE is
	// answered from the device's cache, not executed twice: the very same run.
	expectSamePaths(serial, sim.r);
	EXPECT_EQ(rig.lab->truePose(), sim.truth.final_zxphi);
	EXPECT_EQ(serial.search.T_OinC0_mm.matrix(), sim.r.search.T_OinC0_mm.matrix());
	EXPECT_EQ(serial.retrieval.joints.toMmDeg(), sim.r.retrieval.joints.toMmDeg());
	EXPECT_EQ(serial.shots.size(), sim.r.shots.size());
	ASSERT_EQ(serial.links.size(), 3u);
	EXPECT_GT(totalResends(serial), 0);  // the lost bytes were noticed and resent
	EXPECT_TRUE(sim.r.links.empty());
	EXPECT_GT(rig.emulation->base().emulator().executed(), serial.path.size());
	EXPECT_GE(rig.emulation->head().emulator().executed(), static_cast<size_t>(sim.r.search.views));
	EXPECT_FALSE(rig.lab->arm().gripperClosed());  // it let go of the object over its deck
	EXPECT_EQ(rig.lab->onBoard().count(serial.target), 1u);
	EXPECT_TRUE(serial.place.placed);
	EXPECT_TRUE(rig.report(serial)["eval"]["object_retrieved"].get<bool>());
}

TEST(SerialMission, AnArmThatRefusesAJointLimitStopsTheMission)
{
	// d1: the arm behind the port allows less than planned
	SerialRig rig({}, quickLinks(), [](sim::LabOptions& lo) { lo.arm.max[0] = 1; });
	const auto r = rig.mission->run();
	EXPECT_TRUE(r.stopped);
	EXPECT_FALSE(r.retrieved);
	EXPECT_NE(r.failure.find("refused a command"), std::string::npos) << r.failure;
	EXPECT_NE(r.failure.find("d1"), std::string::npos) << r.failure;
	EXPECT_FALSE(rig.lab->arm().gripperClosed());
}

TEST(SerialMission, AnArmThatStopsAnsweringStopsTheMissionAndKeepsTheRecording)
{
	SerialRig rig;
	hw_serial::FaultOptions hang;
	hang.silent_after_replies = 2;  // GRIP 0 and the pre-grasp MOVE, then nothing
	rig.emulation->arm().emulator().setFaults(hang);
	const auto dir = mission::test::freshTempDir("serial_mission_test_arm_hangs");
	const auto r = rig.runRecorded(dir);
	EXPECT_FALSE(r.success);
	EXPECT_TRUE(r.stopped);
	EXPECT_TRUE(r.found);
	EXPECT_FALSE(r.retrieved);
	EXPECT_NE(r.failure.find("device.arm on " + rig.emulation->arm().slavePath()),
	          std::string::npos)
	    << r.failure;
	EXPECT_NE(r.failure.find("timeout"), std::string::npos) << r.failure;
	// The arm executed ID?, GRIP 0 and one MOVE; the gripper never closed.
	EXPECT_EQ(rig.emulation->arm().emulator().executed(), 3u);
	EXPECT_FALSE(rig.lab->arm().gripperClosed());
	// The base stood still from the last recorded step on, and did not go home.
	ASSERT_FALSE(r.path.empty());
	EXPECT_EQ(r.path.back().device_time_s, rig.lab->simBase().odometry().time_s);
	EXPECT_FALSE(r.returned_home);
	// Everything recorded so far is written and reads back.
	eval::writeMissionOutputs(r, rig.o, nullptr, dir);
	const auto j = nlohmann::json::parse(std::ifstream(dir + "/report.json"));
	EXPECT_FALSE(j["success"].get<bool>());
	EXPECT_TRUE(j["stopped"].get<bool>());
	EXPECT_NE(j["failure"].get<std::string>().find("device.arm"), std::string::npos);
	EXPECT_EQ(j["serial_links"].size(), 3u);
	std::ifstream md(dir + "/report.md");
	EXPECT_NE(std::string(std::istreambuf_iterator<char>(md), {}).find("device.arm on /dev/"),
	          std::string::npos);
	// one record per odometry reading and per stereo pair, the last call the arm's fault
	const auto records = io::readRawlog(dir + "/mission.rawlog");
	size_t pairs = 0;
	for (const auto& rec : records) pairs += rec.has_stereo;
	EXPECT_EQ(pairs, r.shots.size() + size_t(r.navigation_pairs));
	EXPECT_GT(r.shots.size(), 0u);
	const auto calls = readDeviceCalls(dir + "/mission.rawlog").calls;
	ASSERT_FALSE(calls.empty());
	size_t faults = 0;
	for (const auto& c : calls) faults += c.fault.has_value();
	EXPECT_GE(faults, 1u);
	bool arm_fault = false;
	for (const auto& c : calls)
		arm_fault |= c.fault && c.fault->message.find("device.arm") != std::string::npos;
	EXPECT_TRUE(arm_fault);
}

TEST(SerialMission, GarbageFromTheHeadIsAClearErrorAndTheBaseStops)
{
	SerialRig rig;
	hw_serial::FaultOptions garbage;
	garbage.garbage_replies = 1000;
	rig.emulation->head().emulator().setFaults(garbage);
	const auto r = rig.mission->run();
	EXPECT_TRUE(r.stopped);
	EXPECT_FALSE(r.found);
	EXPECT_NE(r.failure.find("device.head on " + rig.emulation->head().slavePath() +
	                         ": garbage: garbage reply"),
	          std::string::npos)
	    << r.failure;
	// The head measures from the first step on (navigation from images): the garbage stops the
	// mission on the way, before any station.
	EXPECT_EQ(r.stations_searched, 0);
	ASSERT_FALSE(r.path.empty());
	EXPECT_EQ(r.path.back().device_time_s, rig.lab->simBase().odometry().time_s);
	bool stopped_note = false;
	for (const auto& e : r.timeline.events()) stopped_note |= e.text == "base stopped";
	EXPECT_TRUE(stopped_note);
}

TEST(SerialMission, ABaseThatHangsAtOnceLeavesAnEmptyButReadableRecord)
{
	SerialRig rig;
	hw_serial::FaultOptions hang;
	hang.silent = true;
	rig.emulation->base().emulator().setFaults(hang);
	const auto dir = mission::test::freshTempDir("serial_mission_test_base_hangs");
	const auto r = rig.runRecorded(dir);
	EXPECT_TRUE(r.stopped);
	EXPECT_NE(r.failure.find("device.base on " + rig.emulation->base().slavePath()),
	          std::string::npos)
	    << r.failure;
	EXPECT_TRUE(r.path.empty());
	bool could_not_stop = false;
	for (const auto& e : r.timeline.events())
		could_not_stop |= e.text.find("could not command the base to stop") == 0;
	EXPECT_TRUE(could_not_stop);
	EXPECT_NO_THROW(eval::writeMissionOutputs(r, rig.o, nullptr, dir));
	EXPECT_TRUE(io::readRawlog(dir + "/mission.rawlog").empty()) << "no odometry, no pair";
	const auto calls = readDeviceCalls(dir + "/mission.rawlog").calls;
	ASSERT_FALSE(calls.empty());
	EXPECT_TRUE(calls.back().fault.has_value()) << "the base's fault is the last call recorded";
}

TEST(SerialMission, WithoutTheHardwareTheMissionFailsNamingPortAndKeyBeforeAnythingMoves)
{
	const auto dir = mission::test::freshTempDir("serial_mission_test_no_hardware", false);
	apps::MissionApp app;
	app.initialize({"mrolr-mission", "--config", test::configDir() + "/mission_hw.ini", "--out",
	                dir, "--set", "device.base.port=/dev/mrolr-no-such-port"});
	std::ostringstream out, progress;
	try
	{
		app.run(out, progress);
		ADD_FAILURE() << "no error";
	}
	catch (const util::ConfigError& e)
	{
		const std::string msg = e.what();
		EXPECT_NE(msg.find("mission_hw.ini with --set [device.base] port"), std::string::npos) << msg;
		EXPECT_NE(msg.find("/dev/mrolr-no-such-port"), std::string::npos) << msg;
	}
	EXPECT_FALSE(fs::exists(dir));
	EXPECT_TRUE(app.result.path.empty());
}

TEST(SerialMission, TheAppRunsTheMissionOnEmulatedDevices)
{
	const auto dir = mission::test::freshTempDir("serial_mission_test_app", false);
	apps::MissionApp app;
	app.initialize({"mrolr-mission", "--config", test::configDir() + "/mission_sim.ini", "--out",
	                dir, "--quiet", "--serial-emulation", "--emulate-delay-ms", "1", "--set",
	                "plan.route=W0", "--set", "mission.home_tolerance_m=0.2"});
	std::ostringstream out, progress;
	EXPECT_EQ(app.run(out, progress), 0) << out.str();
	EXPECT_DOUBLE_EQ(app.options.home_tolerance_m, 0.2);
	ASSERT_EQ(app.result.links.size(), 3u);
	EXPECT_EQ(app.result.links[0].port.rfind("/dev/pts/", 0), 0u) << app.result.links[0].port;
	EXPECT_NE(out.str().find("serial device.arm on /dev/pts/"), std::string::npos) << out.str();
	// --set changes the run, never the file (the key is in mission_sim.ini's base).
	std::ifstream f(test::configDir() + "/mission.ini");
	EXPECT_NE(std::string(std::istreambuf_iterator<char>(f), {}).find("home_tolerance_m = 0.15"),
	          std::string::npos);
}

TEST(SerialMission, BadOverridesAndEmulationOptionsAreUsageErrors)
{
	for (const std::vector<std::string>& args :
	     {std::vector<std::string>{"mrolr-mission", "--set", "noequals"},
	      std::vector<std::string>{"mrolr-mission", "--set", "nosection=1"},
	      std::vector<std::string>{"mrolr-mission", "--emulate-delay-ms", "5"},
	      std::vector<std::string>{"mrolr-mission", "--serial-emulation",
	                               "--emulate-drop-probability", "2"}})
	{
		apps::MissionApp app;
		EXPECT_THROW(app.initialize(args), util::UsageError) << args.back();
	}
}
