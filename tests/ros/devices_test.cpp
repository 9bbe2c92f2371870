// The devices over ROS topics, two processes on a master of the test's own on 127.0.0.1: the
// child serves a simulated lab (DeviceServer), the parent drives it through RosDevices and drives
// a twin lab of the same seed in process. Every answer over ROS is the twin's (exactly where the
// message carries float64: every number of the base, head and cameras; the arm's joints cross
// in SI units and come back within 1e-9 of the thesis's mm and degrees);
// faults come back as the interface's exceptions; a lab that dies or is not there is an error
// naming the device, the topic and the node.
#include "../mission/MissionTestConfig.h"

#include <mrolr/geometry/GeometryError.h>
#include <mrolr/ros/DeviceServer.h>
#include <mrolr/ros/LoopbackMaster.h>
#include <mrolr/ros/RosDevices.h>
#include <mrolr/sim/Lab.h>

#include <gtest/gtest.h>
#include <iostream>
#include <opencv2/core.hpp>
#include <ros/ros.h>

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

using namespace mrolr;

namespace
{
sim::LabOptions labOptions()
{
	return sim::LabOptions::load(mission::test::defaultMissionConfig(), mission::test::configDir());
}

/** The child: the lab on the device topics until it is killed. */
[[noreturn]] void serveLab()
{
	sim::Lab lab(labOptions());
	int argc = 0;
	::ros::init(argc, nullptr, "mrolr_lab", ::ros::init_options::NoSigintHandler);
	{
		::ros::NodeHandle nh;
		mrolr::ros::DeviceServer server(nh, {&lab.base(), &lab.head(), &lab.arm()});
		::ros::spin();
	}
	_exit(0);
}

struct LabChild
{
	pid_t pid = fork();
	LabChild()
	{
		if (pid == 0) serveLab();
	}
	~LabChild() { stop(SIGKILL); }
	void stop(int sig)
	{
		if (pid <= 0) return;
		kill(pid, sig);
		waitpid(pid, nullptr, 0);
		pid = -1;
	}
};

void initRobot()
{
	int argc = 0;
	::ros::init(argc, nullptr, "devices_test_robot", ::ros::init_options::NoSigintHandler);
}

bool samePixels(const mrpt::img::CImage& a, const mrpt::img::CImage& b)
{
	const cv::Mat ma = a.asCvMat<cv::Mat>(mrpt::img::SHALLOW_COPY);
	const cv::Mat mb = b.asCvMat<cv::Mat>(mrpt::img::SHALLOW_COPY);
	return ma.size() == mb.size() && ma.type() == mb.type() && cv::norm(ma, mb, cv::NORM_INF) == 0;
}

void expectSameOdometry(const hw::Odometry& ros, const hw::Odometry& twin)
{
	EXPECT_EQ(ros.ticks_right, twin.ticks_right);
	EXPECT_EQ(ros.ticks_left, twin.ticks_left);
	EXPECT_EQ(ros.xv_zxphi, twin.xv_zxphi);  // float64 joints, the yaw not wrapped
	EXPECT_EQ(ros.time_s, twin.time_s);      // the base's clock as float64, not ROS time's ns
	EXPECT_EQ(ros.bumper, twin.bumper);
}
}  // namespace

TEST(RosDevices, EveryAnswerOverTopicsIsTheLabsOwn)
{
	mrolr::ros::LoopbackMaster master;
	LabChild child;
	ASSERT_GT(child.pid, 0);
	sim::Lab twin(labOptions());
	initRobot();
	::ros::NodeHandle nh;
	mrolr::ros::RosDevices dev(nh, {});
	expectSameOdometry(dev.base.odometry(), twin.base().odometry());
	for (int k = 0; k < 12; ++k)
	{  // steps of any length (a turn's is its angle over the wheel speed), and turns past ±π
		const base::WheelControl u{0.20 + 0.01 * k, -0.25, 0.1 + k / 3.0};
		dev.base.step(u);
		twin.base().step(u);
		expectSameOdometry(dev.base.odometry(), twin.base().odometry());
	}
	const geometry::HeadAngles a{0.2, -0.1, -0.05, 0.06};
	EXPECT_EQ(dev.head.moveTo(a), twin.head().moveTo(a));
	EXPECT_EQ(dev.head.angles().pan, twin.head().angles().pan);
	EXPECT_EQ(dev.head.angles().verg_right, twin.head().angles().verg_right);
	for (int k = 0; k < 2; ++k)
	{
		const auto p = dev.head.grab();
		const auto q = twin.head().grab();
		EXPECT_TRUE(samePixels(p.left, q.left)) << k;
		EXPECT_TRUE(samePixels(p.right, q.right)) << k;
		EXPECT_EQ(p.angles.tilt, q.angles.tilt);
		EXPECT_EQ(p.frame, q.frame);
		EXPECT_EQ(p.time_s, q.time_s);
	}
	EXPECT_EQ(dev.arm.docked(), twin.arm().docked());
	dev.arm.dock(true);
	twin.arm().dock(true);
	EXPECT_TRUE(dev.arm.docked());
	auto j = twin.arm().joints();
	j[1] += 5, j[0] -= 20;
	dev.arm.moveTo(j);
	twin.arm().moveTo(j);
	for (size_t i = 0; i < 7; ++i) EXPECT_NEAR(dev.arm.joints()[i], twin.arm().joints()[i], 1e-9) << i;
	dev.arm.setGripper(true);
	twin.arm().setGripper(true);
	EXPECT_EQ(dev.arm.gripperClosed(), twin.arm().gripperClosed());
	EXPECT_NEAR(dev.arm.gripperWidthMm(), twin.arm().gripperWidthMm(), 1e-9);
}

TEST(RosDevices, ALimitOrARefusalIsTheInterfacesExceptionAndTheDeviceStaysWhereItWas)
{
	mrolr::ros::LoopbackMaster master;
	LabChild child;
	initRobot();
	::ros::NodeHandle nh;
	mrolr::ros::RosDevices dev(nh, {});
	const auto before = dev.head.angles();
	EXPECT_THROW(dev.head.moveTo({0, 3.0, 0, 0}), geometry::FixationError);  // tilt beyond its limit
	EXPECT_EQ(dev.head.angles().tilt, before.tilt);
	dev.arm.dock(true);
	auto j = dev.arm.joints();
	const auto parked = j;
	j[0] = 1e6;  // d1: a kilometre up the column
	EXPECT_THROW(dev.arm.moveTo(j), std::out_of_range);
	EXPECT_EQ(dev.arm.joints()[0], parked[0]);
	// the device still answers after its refusals
	dev.base.step({0.1, 0.1, 0.1});
	EXPECT_GT(dev.base.odometry().ticks_right, 0);
}

TEST(RosDevices, ALabThatDiesStopsTheNextCallNamingTheDeviceAndTheNode)
{
	mrolr::ros::LoopbackMaster master;
	LabChild child;
	initRobot();
	::ros::NodeHandle nh;
	mrolr::ros::RosDeviceOptions o;
	o.timeout_ms = 1500;
	mrolr::ros::RosDevices dev(nh, o);
	dev.base.step({0.1, 0.1, 0.1});
	child.stop(SIGKILL);
	try
	{
		for (int k = 0; k < 3; ++k) dev.base.step({0.1, 0.1, 0.1});
		FAIL() << "a step without a lab returned";
	}
	catch (const hw::DeviceFailure& e)
	{
		const std::string what = e.what();
		EXPECT_NE(what.find("device.base over ROS"), std::string::npos) << what;
		EXPECT_NE(what.find("/base/joint_states"), std::string::npos) << what;
		EXPECT_NE(what.find("/mrolr_lab"), std::string::npos) << what;
		std::cout << "the failure: " << what << "\n";
	}
}

TEST(RosDevices, NoLabIsAnErrorNamingTheTopicAndTheMaster)
{
	mrolr::ros::LoopbackMaster master;
	initRobot();
	::ros::NodeHandle nh;
	mrolr::ros::RosDeviceOptions o;
	o.connect_timeout_ms = 300;
	try
	{
		mrolr::ros::RosDevices dev(nh, o);
		FAIL() << "devices without a lab were built";
	}
	catch (const hw::DeviceFailure& e)
	{
		const std::string what = e.what();
		EXPECT_NE(what.find("/base/command"), std::string::npos) << what;
		EXPECT_NE(what.find(master.uri()), std::string::npos) << what;
	}
}
