// The whole mission through real serial I/O: the simulated lab's base, head and arm are served on
// pseudo-terminals (SerialEmulation), the mission drives them with the serial drivers
// (driver = serial), with faults injected; and devices that stop answering or send garbage.
#include "MissionTestConfig.h"

#include <mrolr/apps/MissionApp.h>
#include <mrolr/io/Rawlog.h>
#include <mrolr/mission/Mission.h>
#include <mrolr/mission/MissionOutputs.h>
#include <mrolr/mission/SerialEmulation.h>
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
hw::LinkOptions quickLinks()
{
	hw::LinkOptions l;
	l.timeout_ms = 100;
	l.motion_timeout_ms = 300;
	l.retries = 2;
	return l;
}

/** A mission on the simulated lab served on ptys; faults can be set before run(). */
struct SerialRig
{
	MissionOptions o;
	std::shared_ptr<SimulatedLab> lab;
	std::unique_ptr<SerialEmulation> emulation;
	std::unique_ptr<Mission> mission;
	explicit SerialRig(const MissionOptions& options, const hw::FaultOptions& faults = {},
	                   const hw::LinkOptions& links = quickLinks())
	    : o(options), lab(std::make_shared<SimulatedLab>(o))
	{
		emulation = std::make_unique<SerialEmulation>(*lab, faults);
		emulation->useIn(o, links);
		mission = std::make_unique<Mission>(o, lab);  // connects: ID? on every port
	}
};

MissionOptions defaults()
{
	return test::optionsFrom(test::defaultMissionConfig());
}

std::string tempDir(const std::string& name)
{
	const auto d = fs::temp_directory_path() / ("mrolr_serial_mission_test_" + name);
	fs::remove_all(d);
	return d.string();
}

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
		EXPECT_EQ(a.path[i].truth, b.path[i].truth) << i;
		EXPECT_EQ(a.path[i].odometry, b.path[i].odometry) << i;
		EXPECT_EQ(a.path[i].estimate, b.path[i].estimate) << i;
	}
}
}  // namespace

TEST(SerialMission, ThroughPtysWithDelaysAndLostBytesItIsTheSimulatedMission)
{
	const auto sim = Mission(defaults()).run();
	hw::FaultOptions faults;
	faults.reply_delay_ms = 1;
	faults.drop_byte_probability = 0.002;
	faults.seed = 5;
	// The seeded drops fall on the same bytes only while the byte flow is the same; on a loaded
	// machine a slow reply is resent, the flow shifts, and with 2 retries one command of the
	// mission's hundreds lost all three replies once (a ~60-byte reply is hit with p ~ 0.11, three
	// in a row ~ 1e-3). With 4 retries that is ~ 2e-5 per command.
	auto links = quickLinks();
	links.retries = 4;
	SerialRig rig(defaults(), faults, links);
	const auto serial = rig.mission->run();
	EXPECT_TRUE(serial.success) << serial.failure;
	EXPECT_EQ(serial.success, sim.success);
	EXPECT_EQ(serial.found_instance, sim.found_instance);
	EXPECT_EQ(serial.retrieved, sim.retrieved);
	// Numbers cross the line exactly (shortest round-trip text), and a resent STEP or MOVE is
	// answered from the device's cache, not executed twice: the very same run.
	expectSamePaths(serial, sim);
	EXPECT_EQ(serial.final_position_error_m, sim.final_position_error_m);
	EXPECT_EQ(serial.search.translation_error_mm, sim.search.translation_error_mm);
	EXPECT_EQ(serial.retrieval.joints.toMmDeg(), sim.retrieval.joints.toMmDeg());
	EXPECT_EQ(serial.shots.size(), sim.shots.size());
	ASSERT_EQ(serial.links.size(), 3u);
	EXPECT_TRUE(serial.links[2].lab_behind_port);
	EXPECT_GT(totalResends(serial), 0);  // the lost bytes were noticed and resent
	EXPECT_TRUE(sim.links.empty());
	EXPECT_GT(rig.emulation->base().emulator().executed(), serial.path.size());
	EXPECT_GE(rig.emulation->head().emulator().executed(), static_cast<size_t>(sim.search.views));
	EXPECT_TRUE(rig.lab->arm().gripperClosed());
}

TEST(SerialMission, DevicesNotServedByTheMissionsLabAreShadowedByIt)
{
	// The emulators serve a lab of their own, as `mrolr-serial emulate` in another process does.
	const auto o_external = defaults();
	SimulatedLab external(o_external);
	SerialEmulation emulation(external);
	auto o = defaults();
	emulation.useIn(o, quickLinks());
	for (auto* d : {&o.devices.base, &o.devices.head, &o.devices.arm}) d->lab_behind_port = false;
	auto lab = std::make_shared<SimulatedLab>(o);
	const auto r = Mission(o, lab).run();
	EXPECT_TRUE(r.success) << r.failure;
	// Same seeds: the devices behind the ports and the mission's shadow lab moved alike.
	EXPECT_EQ(external.truePose(), lab->truePose());
	EXPECT_EQ(external.arm().joints(), lab->arm().joints());
	EXPECT_EQ(external.head().angles().pan, lab->head().angles().pan);
	ASSERT_EQ(r.links.size(), 3u);
	EXPECT_FALSE(r.links[0].lab_behind_port);
	EXPECT_GT(emulation.base().emulator().executed(), r.path.size());
}

TEST(SerialMission, AnArmThatRefusesAJointLimitStopsTheMission)
{
	auto o_external = defaults();
	o_external.sim_arm.max[0] = 1;  // d1: the arm behind the port allows less than planned
	SimulatedLab external(o_external);
	SerialEmulation emulation(external);
	auto o = defaults();
	emulation.useIn(o, quickLinks());
	for (auto* d : {&o.devices.base, &o.devices.head, &o.devices.arm}) d->lab_behind_port = false;
	const auto r = Mission(o, std::make_shared<SimulatedLab>(o)).run();
	EXPECT_TRUE(r.stopped);
	EXPECT_FALSE(r.retrieved);
	EXPECT_NE(r.failure.find("refused a command"), std::string::npos) << r.failure;
	EXPECT_NE(r.failure.find("d1"), std::string::npos) << r.failure;
	EXPECT_FALSE(external.arm().gripperClosed());
}

TEST(SerialMission, AnArmThatStopsAnsweringStopsTheMissionAndKeepsTheRecording)
{
	auto o = defaults();
	o.search.render_stereo = true;
	SerialRig rig(o);
	hw::FaultOptions hang;
	hang.silent_after_replies = 2;  // GRIP 0 and the pre-grasp MOVE, then nothing
	rig.emulation->arm().emulator().setFaults(hang);
	const auto r = rig.mission->run();
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
	EXPECT_EQ(r.path.back().truth, rig.lab->truePose());
	EXPECT_FALSE(r.returned_home);
	// Everything recorded so far is written and reads back.
	const auto dir = tempDir("arm_hangs");
	writeOutputs(r, rig.o, dir);
	const auto j = nlohmann::json::parse(std::ifstream(dir + "/report.json"));
	EXPECT_FALSE(j["success"].get<bool>());
	EXPECT_TRUE(j["stopped"].get<bool>());
	EXPECT_NE(j["failure"].get<std::string>().find("device.arm"), std::string::npos);
	EXPECT_EQ(j["serial_links"].size(), 3u);
	std::ifstream md(dir + "/report.md");
	EXPECT_NE(std::string(std::istreambuf_iterator<char>(md), {}).find("device.arm on /dev/"),
	          std::string::npos);
	const auto records = io::readRawlog(dir + "/mission.rawlog");
	EXPECT_EQ(records.size(), r.path.size() + r.shots.size());
	EXPECT_GT(r.shots.size(), 0u);
}

TEST(SerialMission, GarbageFromTheHeadIsAClearErrorAndTheBaseStops)
{
	SerialRig rig(defaults());
	hw::FaultOptions garbage;
	garbage.garbage_replies = 1000;
	rig.emulation->head().emulator().setFaults(garbage);
	const auto r = rig.mission->run();
	EXPECT_TRUE(r.stopped);
	EXPECT_FALSE(r.found);
	EXPECT_NE(r.failure.find("device.head on " + rig.emulation->head().slavePath() +
	                         ": garbage: garbage reply"),
	          std::string::npos)
	    << r.failure;
	EXPECT_EQ(r.stations_searched, 1);
	ASSERT_FALSE(r.path.empty());
	EXPECT_EQ(r.path.back().truth, rig.lab->truePose());
	bool stopped_note = false;
	for (const auto& e : r.timeline.events()) stopped_note |= e.text == "base stopped";
	EXPECT_TRUE(stopped_note);
}

TEST(SerialMission, ABaseThatHangsAtOnceLeavesAnEmptyButReadableRecord)
{
	SerialRig rig(defaults());
	hw::FaultOptions hang;
	hang.silent = true;
	rig.emulation->base().emulator().setFaults(hang);
	const auto r = rig.mission->run();
	EXPECT_TRUE(r.stopped);
	EXPECT_NE(r.failure.find("device.base on " + rig.emulation->base().slavePath()),
	          std::string::npos)
	    << r.failure;
	EXPECT_TRUE(r.path.empty());
	bool could_not_stop = false;
	for (const auto& e : r.timeline.events())
		could_not_stop |= e.text.find("could not command the base to stop") == 0;
	EXPECT_TRUE(could_not_stop);
	const auto dir = tempDir("base_hangs");
	EXPECT_NO_THROW(writeOutputs(r, rig.o, dir));
	EXPECT_TRUE(io::readRawlog(dir + "/mission.rawlog").empty());
}

TEST(SerialMission, WithoutTheHardwareTheMissionFailsNamingPortAndKeyBeforeAnythingMoves)
{
	const auto dir = tempDir("no_hardware");
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
		EXPECT_NE(msg.find("mission_hw.ini [device.base] port"), std::string::npos) << msg;
		EXPECT_NE(msg.find("/dev/mrolr-no-such-port"), std::string::npos) << msg;
	}
	EXPECT_FALSE(fs::exists(dir));
	EXPECT_TRUE(app.result.path.empty());
}

TEST(SerialMission, TheAppRunsTheMissionOnEmulatedDevices)
{
	const auto dir = tempDir("app");
	apps::MissionApp app;
	app.initialize({"mrolr-mission", "--config", test::configDir() + "/mission_hw.ini", "--out",
	                dir, "--quiet", "--serial-emulation", "--emulate-delay-ms", "1", "--set",
	                "search.render_stereo=false"});
	std::ostringstream out, progress;
	EXPECT_EQ(app.run(out, progress), 0) << out.str();
	EXPECT_FALSE(app.options.search.render_stereo);
	ASSERT_EQ(app.result.links.size(), 3u);
	EXPECT_EQ(app.result.links[0].port.rfind("/dev/pts/", 0), 0u) << app.result.links[0].port;
	EXPECT_NE(out.str().find("serial device.arm on /dev/pts/"), std::string::npos) << out.str();
	// --set changes the run, never the file.
	std::ifstream f(test::configDir() + "/mission_hw.ini");
	EXPECT_NE(std::string(std::istreambuf_iterator<char>(f), {}).find("render_stereo = true"),
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
