// The mission across ROS nodes, as users run it: scripts/ros-mission.sh (a master on loopback,
// mrolr-ros-lab, mrolr-ros-bag, mrolr-ros-robot) gives the in-process mission's result on the
// same seed, its bag reads back with rosbag::View and through MRPT's rosbag2rawlog; a lab killed
// mid-mission stops the robot safely, naming it; the robot never subscribes to the truth.
#include "../common/FreshTempDir.h"
#include "MrptRoundTrip.h"
#include "../mission/ChildProcess.h"

#include <mrolr/apps/MissionApp.h>
#include <mrolr/ros/Conversions.h>
#include <mrolr/ros/LoopbackMaster.h>

#include <geometry_msgs/PoseWithCovarianceStamped.h>
#include <gtest/gtest.h>
#include <nav_msgs/Odometry.h>
#include <nlohmann/json.hpp>
#include <ros/ros.h>
#include <rosbag/bag.h>
#include <rosbag/view.h>
#include <sensor_msgs/Image.h>
#include <tf2/buffer_core.h>
#include <tf2_msgs/TFMessage.h>
#include <xmlrpcpp/XmlRpcValue.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

using namespace mrolr;
using nlohmann::json;

namespace
{
const std::string kBin = MROLR_BIN_DIR;
const std::string kConfig = std::string(MROLR_SOURCE_DIR) + "/config/mission_sim.ini";

json readJson(const std::string& path)
{
	std::ifstream f(path);
	if (!f) throw std::runtime_error("no " + path);
	return json::parse(f);
}

/** The default mission in process, as `mrolr-mission` runs it. */
json inProcessReport(const std::string& dir)
{
	apps::MissionApp app;
	app.initialize({"mrolr-mission", "--config", kConfig, "--out", dir, "--quiet"});
	std::ostringstream out, progress;
	app.run(out, progress);
	return app.report;
}

size_t count(rosbag::Bag& bag, const std::string& topic)
{
	return rosbag::View(bag, rosbag::TopicQuery(topic)).size();
}

/** The very same run: every number the robot reported (its path, map, recognition, grasp and
 * decisions), to the last bit; only compute times and eval's truth checks (the ROS robot has no
 * truth) are left out. */
void expectSameMission(const json& ros, const json& in_process)
{
	for (const auto* key : {"success", "found", "retrieved", "returned_home", "target", "steps",
	                        "navigation_pairs", "measurements", "stereo_pairs"})
		EXPECT_EQ(ros[key], in_process[key]) << key;
	for (const auto* key : {"joints_d1mm_qdeg", "T_OinA_mm", "T_GinA_mm", "width_closed_mm"})
		EXPECT_EQ(ros["retrieval"][key], in_process["retrieval"][key]) << key;
	EXPECT_EQ(ros["robot"], in_process["robot"]);
	EXPECT_EQ(ros["robot"]["path"].size(), in_process["robot"]["path"].size());
}
}  // namespace

TEST(RosMission, TheScriptRunsTheDefaultMissionAsInProcessAndItsBagReadsBack)
{
	const auto dir = test_support::freshTempDir("ros_mission_script");
	const json in_process = inProcessReport(dir + "/in_process");
	ASSERT_TRUE(in_process["success"].get<bool>());

	setenv("MROLR_BIN", kBin.c_str(), 1);  // this build's nodes, whatever the build folder
	test::ChildProcess script({"/bin/bash", std::string(MROLR_SOURCE_DIR) + "/scripts/ros-mission.sh",
	                           "--config", kConfig, "--out", dir + "/ros"});
	std::string out, line;
	while (!(line = script.readLine(240)).empty()) out += line + "\n";
	ASSERT_EQ(script.wait(60), 0) << out;
	EXPECT_NE(out.find("mission"), std::string::npos) << out;  // the summary
	const json ros = readJson(dir + "/ros/report.json");
	EXPECT_EQ(ros["transport"], "ros");
	expectSameMission(ros, in_process);
	{  // its recording replays without a lab, with the run's configuration kept beside it
		apps::MissionApp replay;
		replay.initialize({"mrolr-mission", "--replay", dir + "/ros/mission.rawlog", "--quiet"});
		std::ostringstream o, p;
		EXPECT_EQ(replay.run(o, p), 0) << o.str();
	}

	// the bag: pairs, odometry, joints, tf, the estimate and the truth
	rosbag::Bag bag(dir + "/ros/mission.bag", rosbag::bagmode::Read);
	const size_t pairs = count(bag, "/stereo/left/image_raw");
	EXPECT_GE(pairs, ros["navigation_pairs"].get<size_t>());
	EXPECT_EQ(count(bag, "/stereo/right/image_raw"), pairs);
	EXPECT_EQ(count(bag, "/stereo/left/camera_info"), pairs);
	EXPECT_GT(count(bag, "/odom"), 100u);
	EXPECT_GT(count(bag, "/head/joint_states"), pairs);
	EXPECT_GT(count(bag, "/arm/joint_states"), 0u);
	EXPECT_GT(count(bag, "/tf"), count(bag, "/odom"));
	EXPECT_GT(count(bag, "/mrolr/estimate"), 100u);
	EXPECT_GT(count(bag, "/ground_truth/pose"), 100u);
	EXPECT_EQ(count(bag, "/mrolr/map"), 1u);
	for (const auto& m : rosbag::View(bag, rosbag::TopicQuery("/stereo/left/image_raw")))
	{
		const auto img = m.instantiate<sensor_msgs::Image>();
		ASSERT_TRUE(img);
		EXPECT_TRUE(img->encoding == "mono8" || img->encoding == "bgr8") << img->encoding;
		EXPECT_GT(img->width, 0u);
		EXPECT_EQ(img->data.size(), size_t(img->step) * img->height);
		break;
	}
	// one pose: the last estimate in the bag is the report's final estimate
	geometry_msgs::PoseWithCovarianceStamped::ConstPtr est;
	for (const auto& m : rosbag::View(bag, rosbag::TopicQuery("/mrolr/estimate")))
		est = m.instantiate<geometry_msgs::PoseWithCovarianceStamped>();
	ASSERT_TRUE(est);
	const auto xv = mrolr::ros::planarPoseFrom(est->pose.pose);
	for (int i = 0; i < 3; ++i)
		EXPECT_NEAR(xv[i], ros["robot"]["final_estimate_zxphi"][size_t(i)].get<double>(), 1e-9) << i;
	tf2::BufferCore tf(::ros::Duration(1e6));
	for (const auto& m : rosbag::View(bag, rosbag::TopicQuery("/tf")))
	{
		const auto tfs = m.instantiate<tf2_msgs::TFMessage>();
		for (const auto& t : tfs->transforms) tf.setTransform(t, "bag");
	}
	for (const auto* frame : {"odom", "base_link", "c0", "left_camera", "right_camera", "arm_base",
	                          "gripper"})
		EXPECT_TRUE(tf.canTransform("world", frame, ::ros::Time(0))) << frame;
	bag.close();

	// MRPT's rosbag2rawlog reads every image back
	EXPECT_EQ(test_support::objectsBackFromBag(dir + "/ros/mission.bag", dir + "/back.rawlog"),
	          2 * pairs);
}

namespace
{
/** Node → topics it subscribes to, from the master. */
std::map<std::string, std::set<std::string>> subscriptions()
{
	XmlRpc::XmlRpcValue args, result, payload;
	args[0] = ::ros::this_node::getName();
	std::map<std::string, std::set<std::string>> out;
	if (!::ros::master::execute("getSystemState", args, result, payload, true)) return out;
	auto& subs = payload[1];
	for (int i = 0; i < subs.size(); ++i)
		for (int k = 0; k < subs[i][1].size(); ++k)
			out[std::string(subs[i][1][k])].insert(std::string(subs[i][0]));
	return out;
}
}  // namespace

TEST(RosMission, AKilledLabStopsTheRobotSafelyNamingItAndTheRobotNeverReadsTheTruth)
{
	const auto dir = test_support::freshTempDir("ros_mission_killed_lab");
	mrolr::ros::LoopbackMaster master;
	int argc = 0;
	::ros::init(argc, nullptr, "ros_mission_test", ::ros::init_options::NoSigintHandler);
	test::ChildProcess bag({kBin + "/mrolr-ros-bag", "--out", dir + "/m.bag"});
	ASSERT_NE(bag.readLine(60).find("recording into"), std::string::npos);
	test::ChildProcess lab({kBin + "/mrolr-ros-lab", "--config", kConfig});
	ASSERT_NE(lab.readLine(60).find("serving the lab"), std::string::npos);
	test::ChildProcess robot({kBin + "/mrolr-ros-robot", "--config", kConfig, "--out", dir,
	                          "--quiet", "--timeout-ms", "1500", "--motion-timeout-ms", "3000"});
	// once the robot drives: it subscribes to the devices' replies and never to the truth
	std::map<std::string, std::set<std::string>> subs;
	for (int i = 0; i < 600 && !(subs["/mrolr_robot"].count("/base/joint_states") &&
	                             subs["/mrolr_robot"].count("/arm/joint_states"));
	     ++i)
	{
		::ros::WallDuration(0.05).sleep();
		subs = subscriptions();
	}
	ASSERT_TRUE(subs["/mrolr_robot"].count("/base/joint_states"));
	EXPECT_TRUE(subs["/mrolr_robot"].count("/stereo/left/image_raw"));
	for (const auto& topic : subs["/mrolr_robot"])
		EXPECT_NE(topic.rfind("/ground_truth", 0), 0u) << topic;
	::ros::WallDuration(3.0).sleep();
	lab.signal(SIGKILL);
	EXPECT_EQ(lab.wait(10), 128 + SIGKILL);
	EXPECT_EQ(robot.wait(60), 3);  // ran and failed, safely
	const json r = readJson(dir + "/report.json");
	EXPECT_FALSE(r["success"].get<bool>());
	EXPECT_TRUE(r["stopped"].get<bool>());
	const std::string failure = r["failure"];
	EXPECT_NE(failure.find("over ROS"), std::string::npos) << failure;
	EXPECT_NE(failure.find("/mrolr_lab"), std::string::npos) << failure;
	// what it recorded up to there is in the file, and the bag closes readable on SIGTERM
	EXPECT_GT(std::filesystem::file_size(dir + "/mission.rawlog"), 1000u);
	bag.signal(SIGTERM);
	EXPECT_EQ(bag.wait(30), 0);
	rosbag::Bag b(dir + "/m.bag", rosbag::bagmode::Read);
	EXPECT_GT(count(b, "/stereo/left/image_raw"), 0u);
	EXPECT_GT(count(b, "/mrolr/estimate"), 0u);
	EXPECT_GT(count(b, "/mrolr/stage"), 0u);  // the last one says it stopped
}
