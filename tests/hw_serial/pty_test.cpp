// End to end through real serial I/O: the serial drivers open pseudo-terminals (CSerialPort on the
// slave side) served by device emulators that wrap the simulated devices; the results must equal
// calling the simulated devices directly, also while faults are injected (docs/serial.md).
#include "ExpectSerialError.h"

#include <mrolr/hw_serial/DeviceEmulator.h>
#include <mrolr/hw_serial/SerialFactory.h>
#include <mrolr/sim/SimArm.h>
#include <mrolr/sim/SimBase.h>
#include <mrolr/sim/SimHead.h>
#include <mrolr/util/Config.h>

#include <mrpt/config/CConfigFile.h>
#include <mrpt/config/CConfigFileMemory.h>

#include <gtest/gtest.h>

#include <random>

using namespace mrolr;
using namespace mrolr::hw;
using namespace mrolr::hw_serial;
using Kind = SerialDeviceError::Kind;

namespace
{
mrpt::config::CConfigFileMemory deviceConfig(const std::string& port, int timeout_ms = 300,
                                             int retries = 3)
{
	mrpt::config::CConfigFileMemory cfg;
	cfg.write("device.test", "driver", "serial");
	cfg.write("device.test", "port", port);
	cfg.write("device.test", "baud", 115200);
	cfg.write("device.test", "timeout_ms", timeout_ms);
	cfg.write("device.test", "retries", retries);
	return cfg;
}

sim::SimBaseOptions slippyBase()
{
	sim::SimBaseOptions o;
	o.slip_probability = 0.2;  // slip bursts happen in a short run, so the random stream matters
	o.seed = 7;
	return o;
}

std::vector<base::WheelControl> controls(int n)
{
	std::mt19937 rng(3);
	std::uniform_real_distribution<double> v(-0.3, 0.3);
	std::vector<base::WheelControl> out;
	for (int i = 0; i < n; ++i) out.push_back({v(rng), v(rng), 0.5});
	return out;
}

void expectSameOdometry(const Odometry& a, const Odometry& b, int step)
{
	EXPECT_EQ(a.xv_zxphi, b.xv_zxphi) << "step " << step;
	EXPECT_EQ(a.ticks_right, b.ticks_right) << "step " << step;
	EXPECT_EQ(a.ticks_left, b.ticks_left) << "step " << step;
	EXPECT_EQ(a.time_s, b.time_s) << "step " << step;
}

/** A simulated base behind a pty emulator, and an identical one to call directly. */
struct BaseRig
{
	base::LabmateModel model;
	sim::SimBase direct{model, slippyBase()}, served{model, slippyBase()};
	BaseHandler handler{served};
	PtyEmulator pty;
	explicit BaseRig(const FaultOptions& faults = {}) : pty(handler, faults) {}
	std::unique_ptr<BaseDevice> driver(int timeout_ms = 300, int retries = 3)
	{
		return makeSerialBaseDevice(deviceConfig(pty.slavePath(), timeout_ms, retries),
		                            "device.test");
	}
	void stepBoth(BaseDevice& serial, const base::WheelControl& u)
	{
		serial.step(u);
		direct.step(u);
	}
};

}  // namespace

TEST(PtyEndToEnd, BaseStepsThroughThePtyEqualTheSimulatedBase)
{
	BaseRig rig;
	auto serial = rig.driver();
	int step = 0;
	for (const auto& u : controls(40))
	{
		rig.stepBoth(*serial, u);
		expectSameOdometry(serial->odometry(), rig.direct.odometry(), step++);
	}
	EXPECT_EQ(rig.served.truePose(), rig.direct.truePose());
	EXPECT_GT(rig.direct.slipStepsSoFar(), 0);                // the run did include slip bursts
	EXPECT_EQ(rig.pty.emulator().executed(), 1u + 2u * 40u);  // ID? + STEP/ODO? pairs, no repeats
}

TEST(PtyEndToEnd, HeadMovesThroughThePtyEqualTheSimulatedHead)
{
	const geometry::BiSightHead head;
	sim::StereoRenderer renderer(head, sim::RenderOptions{});
	mrpt::opengl::COpenGLScene scene;
	const auto T_C0inW = [] { return Eigen::Isometry3d::Identity(); };
	sim::SimHead direct(renderer, scene, T_C0inW, {}), served(renderer, scene, T_C0inW, {});
	HeadHandler handler(served);
	PtyEmulator pty(handler);
	auto serial = makeSerialHeadDevice(deviceConfig(pty.slavePath()), "device.test",
	                                   [&] { return served.grab(); });
	const std::vector<geometry::HeadAngles> targets{
	    {0.3, -0.2, 0.05, -0.05}, {-0.35, -0.35, 0.02, -0.02}, {0, 0, 0, 0}, {0.1, 0.2, 0.1, -0.1}};
	for (const auto& t : targets)
	{
		EXPECT_EQ(serial->moveTo(t), direct.moveTo(t));
		const auto a = serial->angles(), b = direct.angles();
		EXPECT_EQ(a.pan, b.pan);
		EXPECT_EQ(a.tilt, b.tilt);
		EXPECT_EQ(a.verg_left, b.verg_left);
		EXPECT_EQ(a.verg_right, b.verg_right);
	}
	EXPECT_THROW(serial->moveTo({10, 0, 0, 0}), geometry::FixationError);
	EXPECT_THROW(direct.moveTo({10, 0, 0, 0}), geometry::FixationError);
	EXPECT_EQ(serial->angles().pan, 0.1);
	const StereoImages pair = serial->grab();
	EXPECT_EQ(pair.left.getWidth(), size_t(head.camera().width_px));
	EXPECT_EQ(pair.angles.tilt, 0.2);
}

TEST(PtyEndToEnd, ArmMovesAndGraspsThroughThePtyEqualTheSimulatedArm)
{
	// a toy kinematics is enough here: the protocol must carry joints and gripper faithfully
	const auto T_GinW = [](const ArmJoints& j)
	{
		Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
		T.translation() = Eigen::Vector3d(j[0] / 1000, j[1] / 100, j[2] / 100);
		return T;
	};
	std::map<std::string, Eigen::Isometry3d> objects_direct, objects_served;
	Eigen::Isometry3d T_OinW = Eigen::Isometry3d::Identity();
	T_OinW.translation() = Eigen::Vector3d(0.5, 0.1, 0);
	objects_direct["cup"] = objects_served["cup"] = T_OinW;
	sim::SimArm direct(T_GinW, {}, objects_direct), served(T_GinW, {}, objects_served);
	ArmHandler handler(served);
	PtyEmulator pty(handler);
	auto serial = makeSerialArmDevice(deviceConfig(pty.slavePath()), "device.test");
	EXPECT_FALSE(serial->docked());
	serial->dock(true);
	direct.dock(true);
	EXPECT_TRUE(serial->docked());
	const std::vector<ArmJoints> moves{
	    {500, 10, 0, 20, -30, 40, 5}, {600, 12.5, 3, 0, 0, 0, -170}, {300, -5, 1, 2, 3, 4, 5}};
	for (size_t i = 0; i < moves.size(); ++i)
	{
		serial->moveTo(moves[i]);
		direct.moveTo(moves[i]);
		EXPECT_EQ(serial->joints(), direct.joints());
		if (i == 0)
		{
			serial->setGripper(true);
			direct.setGripper(true);
		}
	}
	EXPECT_TRUE(serial->gripperClosed());
	// no gripper physics here: both close on nothing and report the same width
	EXPECT_EQ(served.grasped(), direct.grasped());
	EXPECT_DOUBLE_EQ(serial->gripperWidthMm(), direct.gripperWidthMm());
	EXPECT_TRUE(objects_served["cup"].isApprox(objects_direct["cup"], 0));
	EXPECT_THROW(serial->moveTo({2000, 0, 0, 0, 0, 0, 0}), std::out_of_range);
	EXPECT_EQ(serial->joints(), direct.joints());
}

TEST(PtyFaults, ADelayedReplyWithinTheTimeoutSucceedsWithoutResending)
{
	FaultOptions f;
	f.reply_delay_ms = 80;
	BaseRig rig(f);
	auto serial = rig.driver(1000, 2);  // far above the delay, so a loaded machine cannot resend
	rig.stepBoth(*serial, {0.1, 0.1, 0.5});
	expectSameOdometry(serial->odometry(), rig.direct.odometry(), 0);
	EXPECT_EQ(rig.pty.emulator().received(), 3u);  // ID?, STEP, ODO?: nothing was resent
}

TEST(PtyFaults, DroppedBytesAreRetriedAndTheStepIsExecutedOnce)
{
	BaseRig rig;
	auto serial = rig.driver(1000, 3);  // damaged replies are resent at once, not after the timeout
	FaultOptions f;
	f.drop_byte_replies = 2;
	rig.pty.emulator().setFaults(f);
	rig.stepBoth(*serial, {0.2, 0.1, 0.5});  // two damaged replies, then the cached third
	expectSameOdometry(serial->odometry(), rig.direct.odometry(), 0);
	EXPECT_EQ(rig.pty.emulator().received(), 1u + 3u + 1u);
	EXPECT_EQ(rig.pty.emulator().executed(), 3u);  // ID?, STEP once, ODO?
}

TEST(PtyFaults, RandomByteLossStillGivesExactlyTheSimulatedRun)
{
	FaultOptions f;
	f.drop_byte_probability = 0.003;  // about one reply in four damaged
	f.seed = 11;
	BaseRig rig(f);
	auto serial = rig.driver(150, 10);
	int step = 0;
	for (const auto& u : controls(30))
	{
		rig.stepBoth(*serial, u);
		expectSameOdometry(serial->odometry(), rig.direct.odometry(), step++);
	}
	EXPECT_GT(rig.pty.emulator().received(), rig.pty.emulator().executed());  // some were resent
	EXPECT_EQ(rig.pty.emulator().executed(), 1u + 2u * 30u);
}

TEST(PtyFaults, PersistentGarbageIsReportedNamingDeviceAndPort)
{
	BaseRig rig;
	auto serial = rig.driver(100, 2);
	FaultOptions f;
	f.garbage_replies = 100;
	rig.pty.emulator().setFaults(f);
	const auto e = expectSerialError([&] { serial->step({0.1, 0.1, 0.5}); });
	EXPECT_EQ(e.kind(), Kind::Garbage);
	EXPECT_EQ(e.device(), "device.test");
	EXPECT_EQ(e.port(), rig.pty.slavePath());
	EXPECT_NE(std::string(e.what()).find("garbage reply '\\x13\\xFF\\x00 garbage \\x80\\x7F'"),
	          std::string::npos)
	    << e.what();
	EXPECT_NE(std::string(e.what()).find("after 3 attempts of 600 ms (command STEP)"),
	          std::string::npos)
	    << e.what();
}

TEST(PtyFaults, ADeviceThatStopsAnsweringGivesATimeoutAndNeverHangs)
{
	BaseRig rig;
	auto serial = rig.driver(100, 2);
	rig.stepBoth(*serial, {0.1, 0.1, 0.5});
	FaultOptions f;
	f.silent = true;
	rig.pty.emulator().setFaults(f);
	const auto e = expectSerialError([&] { serial->odometry(); });
	EXPECT_EQ(e.kind(), Kind::Timeout);
	EXPECT_EQ(std::string(e.what()), "device.test on " + rig.pty.slavePath() +
	                                     ": timeout: no reply after 3 attempts of 100 ms (command "
	                                     "ODO?)");
	rig.pty.emulator().setFaults({});  // the device recovers: the link works again
	expectSameOdometry(serial->odometry(), rig.direct.odometry(), 1);
}

TEST(PtyFaults, ADeviceThatHangsAfterNRepliesAnswersExactlyN)
{
	BaseRig rig;
	auto serial = rig.driver(100, 1);
	FaultOptions f;
	f.silent_after_replies = 2;
	rig.pty.emulator().setFaults(f);
	rig.stepBoth(*serial, {0.1, 0.1, 0.5});
	expectSameOdometry(serial->odometry(), rig.direct.odometry(), 1);
	const size_t executed = rig.pty.emulator().executed();
	const auto e = expectSerialError([&] { serial->step({0.1, 0.1, 0.5}); });
	EXPECT_EQ(e.kind(), Kind::Timeout);
	EXPECT_EQ(rig.pty.emulator().executed(), executed);  // the third request was not executed
}

TEST(PtyFaults, AHungUpPortIsReportedAsADisconnect)
{
	BaseRig rig;
	auto serial = rig.driver(100, 5);
	rig.stepBoth(*serial, {0.1, 0.1, 0.5});
	rig.pty.hangUp();
	const auto e = expectSerialError([&] { serial->step({0.1, 0.1, 0.5}); });
	EXPECT_EQ(e.kind(), Kind::Disconnected);
	EXPECT_NE(
	    std::string(e.what()).find("device.test on " + rig.pty.slavePath() + ": disconnected"),
	    std::string::npos)
	    << e.what();
}

TEST(SerialFactory, ConfigErrorsNameTheKey)
{
	mrpt::config::CConfigFileMemory cfg;
	cfg.write("device.base", "driver", "serial");
	cfg.write("device.base", "baud", 9600);
	try
	{
		makeSerialBaseDevice(cfg, "device.base");
		FAIL() << "no throw";
	}
	catch (const util::ConfigError& e)
	{
		EXPECT_NE(std::string(e.what()).find("[device.base] port"), std::string::npos) << e.what();
	}
	cfg.write("device.base", "port", "/dev/ttyUSB0");
	cfg.write("device.base", "retries", "three");
	EXPECT_THROW(makeSerialBaseDevice(cfg, "device.base"), util::ConfigError);
	cfg.write("device.base", "retries", -1);
	EXPECT_THROW(makeSerialBaseDevice(cfg, "device.base"), util::ConfigError);
}

TEST(SerialFactory, AMissingPortIsADisconnectNamingIt)
{
	auto cfg = deviceConfig("/dev/mrolr-no-such-port");
	const auto e = expectSerialError([&] { makeSerialArmDevice(cfg, "device.test"); });
	EXPECT_EQ(e.kind(), Kind::Disconnected);
	EXPECT_EQ(e.port(), "/dev/mrolr-no-such-port");
	EXPECT_NE(std::string(e.what()).find("cannot open the serial port"), std::string::npos);
}

TEST(SerialFactory, TheShippedHardwareConfigReadsForEveryDevice)
{
	const mrpt::config::CConfigFile cfg(std::string(MROLR_SOURCE_DIR) + "/config/mission_hw.ini");
	for (const char* section : {"device.base", "device.head", "device.arm"})
	{
		SerialLinkConfig link;
		ASSERT_NO_THROW(link.loadFromConfigFile(cfg, section)) << section;
		EXPECT_EQ(util::readString(cfg, section, "driver"), "serial");
		EXPECT_EQ(link.link.device, section);
		EXPECT_GT(link.link.motion_timeout_ms, link.link.timeout_ms);
	}
}
