// Two processes on a master of the test's own, on 127.0.0.1: a stereo pair published by one
// arrives in the other with its pixels, encoding, frame and time.
#include <mrolr/ros/LoopbackMaster.h>

#include <mrolr/ros/Conversions.h>

#include <gtest/gtest.h>
#include <opencv2/core.hpp>
#include <ros/ros.h>

#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <vector>

namespace
{
cv::Mat imageNumber(int k)
{
	cv::Mat m(480, 640, CV_8UC1);
	cv::theRNG().state = 100 + k;
	cv::randu(m, 0, 256);
	return m;
}

/** The child: publishes @p n images on /stereo/left/image_raw once a subscriber is there. */
[[noreturn]] void publishImages(int n)
{
	int argc = 0;
	::ros::init(argc, nullptr, "loopback_test_publisher", ::ros::init_options::NoSigintHandler);
	::ros::NodeHandle nh;
	auto pub = nh.advertise<sensor_msgs::Image>("/stereo/left/image_raw", n);
	for (int i = 0; i < 400 && pub.getNumSubscribers() == 0; ++i) ::ros::Duration(0.025).sleep();
	for (int k = 0; k < n; ++k)
	{
		pub.publish(mrolr::ros::toImageMsg(mrpt::img::CImage(imageNumber(k), mrpt::img::SHALLOW_COPY),
		                                   0.5 * k, "left_camera"));
		::ros::Duration(0.02).sleep();
	}
	::ros::Duration(0.5).sleep();
	::ros::shutdown();
	_exit(0);
}
}  // namespace

TEST(RosLoopback, ImagesPublishedByAnotherProcessArriveWithTheirPixels)
{
	mrolr::ros::LoopbackMaster master;
	constexpr int kImages = 5;
	const pid_t child = fork();
	ASSERT_GE(child, 0);
	if (child == 0) publishImages(kImages);
	int argc = 0;
	::ros::init(argc, nullptr, "loopback_test_subscriber", ::ros::init_options::NoSigintHandler);
	std::vector<sensor_msgs::Image::ConstPtr> got;
	{
		::ros::NodeHandle nh;
		auto sub = nh.subscribe<sensor_msgs::Image>(
		    "/stereo/left/image_raw", kImages,
		    [&got](const sensor_msgs::Image::ConstPtr& m) { got.push_back(m); });
		const auto end = ::ros::WallTime::now() + ::ros::WallDuration(20);
		while (got.size() < size_t(kImages) && ::ros::WallTime::now() < end) ::ros::spinOnce();
	}
	::ros::shutdown();
	int status = 0;
	waitpid(child, &status, 0);
	EXPECT_EQ(WEXITSTATUS(status), 0);
	ASSERT_EQ(got.size(), size_t(kImages)) << "on " << master.uri();
	for (int k = 0; k < kImages; ++k)
	{
		EXPECT_EQ(got[k]->encoding, "mono8");
		EXPECT_EQ(got[k]->header.frame_id, "left_camera");
		EXPECT_NEAR(mrolr::ros::fromRosTime(got[k]->header.stamp), 0.5 * k, 1e-6);
		const cv::Mat back = mrolr::ros::fromImageMsg(*got[k]).asCvMat<cv::Mat>(mrpt::img::SHALLOW_COPY);
		EXPECT_EQ(cv::norm(back, imageNumber(k), cv::NORM_INF), 0) << k;
	}
}
