// A mission's recording as a ROS bag: every pair, odometry reading and truth record in it, with
// the right encodings, sizes and poses; and MRPT's own rosbag2rawlog reads every image back.
#include <mrolr/apps/MissionApp.h>
#include <mrolr/apps/Rawlog2BagApp.h>
#include <mrolr/io/Rawlog.h>
#include <mrolr/util/Cli.h>
#include <mrolr/ros/Conversions.h>

#include <geometry_msgs/PoseStamped.h>
#include <geometry_msgs/PoseWithCovarianceStamped.h>
#include "../common/FreshTempDir.h"
#include "MrptRoundTrip.h"

#include <gtest/gtest.h>
#include <nav_msgs/Odometry.h>
#include <rosbag/bag.h>
#include <rosbag/view.h>
#include <tf2/buffer_core.h>
#include <tf2_msgs/TFMessage.h>
#include <sensor_msgs/Image.h>

#include <filesystem>
#include <fstream>
#include <sstream>

using namespace mrolr;
namespace fs = std::filesystem;

namespace
{
/** A short mission recorded by mrolr-mission: the route runs into the table (a few pairs). */
std::string recordMission(const std::string& dir)
{
	std::ofstream(dir + "/plan.ini") << "[plan]\nroute = W0 T\nstations = W5\nhome = W6\n"
	                                    "[waypoints]\nW0 = 0 0 0\nT = 2.4 0 0\nW5 = 0.5 0 0\n"
	                                    "W6 = 0 0 0\n";
	apps::MissionApp app;
	app.initialize({"mrolr-mission", "--config", std::string(MROLR_SOURCE_DIR) + "/config/mission_sim.ini",
	                "--plan", dir + "/plan.ini", "--set", "mission.obstacle_mode=false", "--out",
	                dir + "/run", "--quiet"});
	std::ostringstream out, progress;
	app.run(out, progress);
	return dir + "/run/mission.rawlog";
}
}  // namespace

TEST(Rawlog2Bag, AMissionsRecordingBecomesABagWithEveryPairOdometryAndTruth)
{
	const auto dir = mrolr::test_support::freshTempDir("rawlog2bag_mission");
	const auto rawlog = recordMission(dir);
	const auto records = io::readRawlog(rawlog);
	size_t pairs = 0, truths = 0, estimates = 0;
	for (const auto& r : records)
		pairs += r.has_stereo, truths += !r.has_stereo && r.true_zxphi.has_value(),
		    estimates += r.estimate_zxphi.has_value();
	ASSERT_GT(estimates, 0u);
	ASSERT_GT(pairs, 3u);
	apps::Rawlog2BagApp app;
	app.initialize({"mrolr-rawlog2bag", rawlog, dir + "/m.bag", "--quiet"});
	std::ostringstream out, progress;
	ASSERT_EQ(app.run(out, progress), 0);
	EXPECT_EQ(app.summary.pairs, pairs);

	rosbag::Bag bag(dir + "/m.bag", rosbag::bagmode::Read);
	std::map<std::string, size_t> count;
	for (const auto& m : rosbag::View(bag)) ++count[m.getTopic()];
	EXPECT_EQ(count["/stereo/left/image_raw"], pairs);
	EXPECT_EQ(count["/stereo/right/image_raw"], pairs);
	EXPECT_EQ(count["/stereo/left/camera_info"], pairs);
	EXPECT_EQ(count["/odom"], records.size() - pairs);
	EXPECT_EQ(count["/ground_truth/pose"], truths);
	EXPECT_EQ(count["/mrolr/estimate"], estimates);
	EXPECT_EQ(count["/tf_static"], 0u) << "world → odom comes with each estimate";
	EXPECT_EQ(count["/tf"], (records.size() - pairs) + 2 * pairs + estimates);
	// the first pair's images: mono8, full size, the recorded pixels
	const io::RawlogRecord* first = nullptr;
	for (const auto& r : records)
		if (r.has_stereo && !first) first = &r;
	for (const auto& m : rosbag::View(bag, rosbag::TopicQuery("/stereo/right/image_raw")))
	{
		const auto img = m.instantiate<sensor_msgs::Image>();
		ASSERT_TRUE(img);
		EXPECT_EQ(img->encoding, "mono8");
		EXPECT_EQ(img->width, 640u);
		EXPECT_EQ(img->height, 480u);
		const cv::Mat back = mrolr::ros::fromImageMsg(*img).asCvMat<cv::Mat>(mrpt::img::SHALLOW_COPY);
		EXPECT_EQ(cv::norm(back, first->right.asCvMat<cv::Mat>(mrpt::img::SHALLOW_COPY), cv::NORM_INF), 0);
		EXPECT_NEAR(mrolr::ros::fromRosTime(img->header.stamp), first->time_s, 1e-6);
		break;
	}
	// one pose: the last odometry reading
	const io::RawlogRecord* last = nullptr;
	for (const auto& r : records)
		if (!r.has_stereo) last = &r;
	nav_msgs::Odometry::ConstPtr odo;
	for (const auto& m : rosbag::View(bag, rosbag::TopicQuery("/odom")))
		odo = m.instantiate<nav_msgs::Odometry>();
	ASSERT_TRUE(odo);
	EXPECT_TRUE(mrolr::ros::fromPoseMsg(odo->pose.pose).isApprox(mrolr::ros::planarPose(last->odometry_zxphi), 1e-12));
	// the last estimate: its pose and covariance
	const io::RawlogRecord* estimated = nullptr;
	for (const auto& r : records)
		if (r.estimate_zxphi) estimated = &r;
	geometry_msgs::PoseWithCovarianceStamped::ConstPtr est;
	for (const auto& m : rosbag::View(bag, rosbag::TopicQuery("/mrolr/estimate")))
		est = m.instantiate<geometry_msgs::PoseWithCovarianceStamped>();
	ASSERT_TRUE(est);
	EXPECT_TRUE(mrolr::ros::fromPoseMsg(est->pose.pose)
	                .isApprox(mrolr::ros::planarPose(*estimated->estimate_zxphi), 1e-12));
	EXPECT_TRUE(mrolr::ros::planarCovarianceFrom(est->pose.covariance).isApprox(estimated->estimate_P));
	EXPECT_GT(estimated->estimate_P(0, 0), 0.0);
	// tf joins world to both cameras (what rosbag2rawlog and RViz need); at the bag's end
	// world → base_link is the last estimate
	tf2::BufferCore tf(::ros::Duration(1e6));
	for (const auto& m : rosbag::View(bag, rosbag::TopicQuery("/tf")))
	{
		const auto tfs = m.instantiate<tf2_msgs::TFMessage>();  // kept alive while read
		for (const auto& t : tfs->transforms) tf.setTransform(t, "bag");
	}
	EXPECT_TRUE(tf.canTransform("world", "right_camera", ::ros::Time(0)));
	// world → base_link at the end: the last estimate's correction applied to the last odometry
	const Eigen::Isometry3d expected = mrolr::ros::planarPose(*estimated->estimate_zxphi) *
	                                   mrolr::ros::planarPose(estimated->odometry_zxphi).inverse() *
	                                   mrolr::ros::planarPose(last->odometry_zxphi);
	const auto wb = tf.lookupTransform("world", "base_link", ::ros::Time(0));
	EXPECT_NEAR(wb.transform.translation.x, expected.translation().x(), 1e-9);
	EXPECT_NEAR(wb.transform.translation.y, expected.translation().y(), 1e-9);
	bag.close();

	// MRPT's rosbag2rawlog, with the shipped configuration, gives every image back
	EXPECT_EQ(test_support::objectsBackFromBag(dir + "/m.bag", dir + "/back.rawlog"), 2 * pairs);
}

TEST(Rawlog2Bag, BadArgumentsAndUnreadableFilesAreNamed)
{
	apps::Rawlog2BagApp app;
	EXPECT_THROW(app.initialize({"mrolr-rawlog2bag", "in.rawlog", "out.txt"}), util::UsageError);
	apps::Rawlog2BagApp missing;
	missing.initialize({"mrolr-rawlog2bag", "/nonexistent/in.rawlog", "/tmp/x.bag"});
	std::ostringstream out, progress;
	try
	{
		missing.run(out, progress);
		ADD_FAILURE() << "a missing rawlog converted";
	}
	catch (const std::runtime_error& e)
	{
		EXPECT_NE(std::string(e.what()).find("/nonexistent/in.rawlog"), std::string::npos);
	}
	const auto dir = mrolr::test_support::freshTempDir("rawlog2bag_garbage");
	std::ofstream(dir + "/g.rawlog") << "garbage";
	apps::Rawlog2BagApp garbage;
	garbage.initialize({"mrolr-rawlog2bag", dir + "/g.rawlog", dir + "/g.bag", "--quiet"});
	EXPECT_THROW(garbage.run(out, progress), std::runtime_error);
}
