// A recording answers a replay with exactly what the devices answered, faults included, and never
// answers what it does not hold.
#include "MissionTestConfig.h"
#include "../common/ThrownMessage.h"

#include <mrolr/geometry/GeometryError.h>
#include <mrolr/hw_serial/SerialError.h>
#include <mrolr/mission/DevicePlayback.h>
#include <mrolr/mission/DeviceRecorder.h>

#include <gtest/gtest.h>

#include <filesystem>
#include <random>

using namespace mrolr;
namespace fs = std::filesystem;

namespace
{
/** Devices with answers drawn at random (so equal answers cannot come from a default). */
struct RandomDevices : hw::BaseDevice, hw::HeadDevice, hw::ArmDevice
{
	mutable std::mt19937 rng{7};
	double any() const { return std::uniform_real_distribution<>(-3, 3)(rng); }
	uint64_t frames = 0;
	bool fail_next_move = false;
	// base
	void step(const base::WheelControl&) override {}
	hw::Odometry odometry() const override
	{
		hw::Odometry o;
		o.xv_zxphi = {any(), any(), any()};
		o.ticks_right = long(any() * 1000), o.ticks_left = long(any() * 1000);
		o.time_s = 10 + any();
		o.bumper = any() > 0;
		return o;
	}
	// head
	double moveTo(const geometry::HeadAngles&) override
	{
		if (fail_next_move) throw geometry::FixationError("pan beyond its limit");
		return any();
	}
	geometry::HeadAngles angles() const override { return {any(), any(), any(), any()}; }
	hw::StereoImages grab() override
	{
		hw::StereoImages p;
		cv::Mat l(48, 64, CV_8UC1), r(48, 64, CV_8UC1);
		cv::randu(l, 0, 255), cv::randu(r, 0, 255);
		p.left = mrpt::img::CImage(l, mrpt::img::DEEP_COPY);
		p.right = mrpt::img::CImage(r, mrpt::img::DEEP_COPY);
		p.angles = angles();
		p.time_s = 20 + any();
		p.frame = frames++;
		return p;
	}
	// arm
	void moveTo(const hw::ArmJoints& j) override
	{
		if (j[0] < 0) throw hw::ArmBlocked("the hand met the table at d1 = 300 mm");
		if (j[1] > 1000)
			throw hw_serial::SerialDeviceError(hw_serial::SerialDeviceError::Kind::Timeout, "device.arm",
			                            "/dev/pts/9", "no reply after 4 attempts");
	}
	hw::ArmJoints joints() const override { return {any(), any(), any(), any(), any(), any(), any()}; }
	void setGripper(bool) override {}
	bool gripperClosed() const override { return any() > 0; }
	double gripperWidthMm() const override { return any() * 30; }
	void dock(bool d) override
	{
		if (!d) throw std::logic_error("the arm holds 'cube': it stays docked");
	}
	bool docked() const override { return true; }
};

mission::RobotDevices devicesOf(RandomDevices& d)
{
	mission::RobotDevices out;
	out.base = &d, out.head = &d, out.arm = &d;
	return out;
}

/** The same requests made of any devices, with what they answered written out as numbers. */
std::vector<double> session(mission::RobotDevices d, std::atomic<bool>* stop_seen = nullptr,
                            std::atomic<bool>* stop_flag = nullptr)
{
	std::vector<double> out;
	auto note = [&](std::initializer_list<double> v) { out.insert(out.end(), v); };
	d.base->step({0.1, 0.2, 0.5});
	const auto o = d.base->odometry();
	note({o.xv_zxphi[0], o.xv_zxphi[1], o.xv_zxphi[2], double(o.ticks_right), o.time_s,
	      double(o.bumper)});
	note({d.head->moveTo({0.1, -0.2, 0.3, 0.3})});
	const auto p = d.head->grab();
	note({p.angles.pan, p.time_s, double(p.frame)});
	const cv::Mat l = p.left.asCvMat<cv::Mat>(mrpt::img::SHALLOW_COPY);
	note({cv::sum(l)[0], double(l.rows), double(l.cols)});
	if (stop_seen && stop_flag) *stop_seen = stop_flag->load();
	for (double v : d.arm->joints()) out.push_back(v);
	note({d.arm->gripperWidthMm(), double(d.arm->gripperClosed()), double(d.arm->docked())});
	const auto a = d.head->angles();
	note({a.pan, a.tilt, a.verg_left, a.verg_right});
	return out;
}

template <typename E>
std::string thrownBy(const std::function<void()>& f)
{
	return mrolr::test_support::messageOf<E>(f, "nothing thrown");
}
}  // namespace

TEST(DeviceRecording, APlaybackAnswersEveryRequestWithExactlyWhatTheDevicesAnswered)
{
	const auto dir = mission::test::freshTempDir("device_recording_answers");
	RandomDevices dev;
	std::vector<double> live;
	{
		mission::DeviceRecorder rec(dir + "/r.rawlog", devicesOf(dev), geometry::BiSightHead());
		live = session(rec.devices());
		EXPECT_EQ(rec.calls(), 9u);
	}
	mission::DevicePlayback play(dir + "/r.rawlog");
	EXPECT_EQ(play.recorded(), 9u);
	EXPECT_EQ(session(play.devices()), live);  // bit for bit, images included
	EXPECT_EQ(play.served(), 9u);
	EXPECT_TRUE(play.torn().empty());
}

TEST(DeviceRecording, FaultsReplayAsTheSameExceptionWithTheSameMessage)
{
	const auto dir = mission::test::freshTempDir("device_recording_faults");
	RandomDevices dev;
	std::vector<std::string> live;
	auto faults = [](mission::RobotDevices d)
	{
		std::vector<std::string> w;
		w.push_back(thrownBy<hw::ArmBlocked>([&] { d.arm->moveTo({-1, 0, 0, 0, 0, 0, 0}); }));
		w.push_back(thrownBy<hw_serial::SerialDeviceError>([&] { d.arm->moveTo({1, 2000, 0, 0, 0, 0, 0}); }));
		w.push_back(thrownBy<std::logic_error>([&] { d.arm->dock(false); }));
		return w;
	};
	{
		mission::DeviceRecorder rec(dir + "/r.rawlog", devicesOf(dev), geometry::BiSightHead());
		live = faults(rec.devices());
		dev.fail_next_move = true;
		live.push_back(thrownBy<geometry::FixationError>(
		    [&] { rec.devices().head->moveTo({2, 0, 0.1, 0.1}); }));
	}
	EXPECT_EQ(live[0], "the hand met the table at d1 = 300 mm");
	EXPECT_NE(live[1].find("device.arm on /dev/pts/9: timeout"), std::string::npos) << live[1];
	mission::DevicePlayback play(dir + "/r.rawlog");
	auto replayed = faults(play.devices());
	replayed.push_back(
	    thrownBy<geometry::FixationError>([&] { play.devices().head->moveTo({2, 0, 0.1, 0.1}); }));
	EXPECT_EQ(replayed, live);
	// the serial fault keeps its kind, device and port, which the mission decides on
	mission::DevicePlayback again(dir + "/r.rawlog");
	auto arm = again.devices().arm;
	EXPECT_THROW(arm->moveTo({-1, 0, 0, 0, 0, 0, 0}), hw::ArmBlocked);
	try
	{
		arm->moveTo({1, 2000, 0, 0, 0, 0, 0});
		ADD_FAILURE() << "no fault replayed";
	}
	catch (const hw_serial::SerialDeviceError& e)
	{
		EXPECT_EQ(e.kind(), hw_serial::SerialDeviceError::Kind::Timeout);
		EXPECT_EQ(e.device(), "device.arm");
		EXPECT_EQ(e.port(), "/dev/pts/9");
	}
}

TEST(DeviceRecording, ARequestTheRecordingDoesNotHoldIsADivergenceNamingCallDeviceAndValues)
{
	const auto dir = mission::test::freshTempDir("device_recording_divergence");
	RandomDevices dev;
	{
		mission::DeviceRecorder rec(dir + "/r.rawlog", devicesOf(dev), geometry::BiSightHead());
		session(rec.devices());
	}
	mission::DevicePlayback play(dir + "/r.rawlog");
	auto d = play.devices();
	d.base->step({0.1, 0.2, 0.5});
	d.base->odometry();
	// one bit off in a value is another request
	const double pan = std::nextafter(0.1, 1.0);
	const auto what = thrownBy<hw::ReplayDivergence>([&] { d.head->moveTo({pan, -0.2, 0.3, 0.3}); });
	EXPECT_NE(what.find("device call 2 of 9"), std::string::npos) << what;
	EXPECT_NE(what.find("head.moveTo(0.10000000000000002"), std::string::npos) << what;
	EXPECT_NE(what.find("the recording has head.moveTo(0.10000000000000001"), std::string::npos)
	    << what;
	// another device, and past the end
	mission::DevicePlayback other(dir + "/r.rawlog");
	EXPECT_NE(thrownBy<hw::ReplayDivergence>([&] { other.devices().arm->joints(); }).find("arm.joints()"),
	          std::string::npos);
	mission::DevicePlayback all(dir + "/r.rawlog");
	session(all.devices());
	EXPECT_NE(thrownBy<hw::ReplayDivergence>([&] { all.devices().base->odometry(); })
	              .find("after the recording's last call"),
	          std::string::npos);
}

TEST(DeviceRecording, AStopRequestIsRaisedInTheReplayAtTheCallWhereTheRunRaisedIt)
{
	const auto dir = mission::test::freshTempDir("device_recording_stop");
	RandomDevices dev;
	std::atomic<bool> signal{false};
	std::atomic<bool> seen_live{false}, seen_replay{false};
	{
		mission::DeviceRecorder rec(dir + "/r.rawlog", devicesOf(dev), geometry::BiSightHead());
		auto& flag = rec.stopFlag(&signal);
		auto d = rec.devices();
		d.base->step({0.1, 0.2, 0.5});
		EXPECT_FALSE(flag.load());
		signal = true;  // a SIGINT arrives between two calls ...
		EXPECT_FALSE(flag.load()) << "... and reaches the mission only at the next device call";
		d.base->odometry();
		seen_live = flag.load();
	}
	EXPECT_TRUE(seen_live.load());
	mission::DevicePlayback play(dir + "/r.rawlog");
	auto d = play.devices();
	d.base->step({0.1, 0.2, 0.5});
	EXPECT_FALSE(play.stopFlag().load());
	d.base->odometry();
	seen_replay = play.stopFlag().load();
	EXPECT_TRUE(seen_replay.load());
}

TEST(DeviceRecording, ATornLastRecordIsLeftOutAndNamed)
{
	const auto dir = mission::test::freshTempDir("device_recording_torn");
	RandomDevices dev;
	{
		mission::DeviceRecorder rec(dir + "/r.rawlog", devicesOf(dev), geometry::BiSightHead());
		session(rec.devices());
	}
	const auto size = fs::file_size(dir + "/r.rawlog");
	fs::resize_file(dir + "/r.rawlog", size - 5);  // the writer killed inside its last record
	const auto log = io::readObservationLog(dir + "/r.rawlog");
	EXPECT_NE(log.torn.find("incomplete"), std::string::npos) << log.torn;
	mission::DevicePlayback play(dir + "/r.rawlog");
	EXPECT_EQ(play.recorded(), 8u) << "the last call was torn: the eight before it are whole";
	EXPECT_FALSE(play.torn().empty());
}

TEST(DeviceRecording, GarbageInsteadOfARawlogIsNamedNotCrashedOn)
{
	const auto dir = mission::test::freshTempDir("device_recording_garbage");
	std::ofstream(dir + "/g.rawlog") << "this is not a rawlog at all\n";
	for (const char* name : {"/g.rawlog", "/missing.rawlog"})
		try
		{
			mission::DevicePlayback play(dir + name);
			ADD_FAILURE() << name << " was taken for a recording";
		}
		catch (const std::runtime_error& e)
		{
			EXPECT_NE(std::string(e.what()).find(name), std::string::npos) << e.what();
		}
}
