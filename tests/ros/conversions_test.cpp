// MROLR ⇄ ROS messages: images keep their pixels and say what they hold, poses, covariances and
// times round-trip, and a message that cannot be converted is named.
#include <mrolr/geometry/Frames.h>
#include <mrolr/ros/Conversions.h>

#include <gtest/gtest.h>
#include <opencv2/core.hpp>

#include <random>

using namespace mrolr;

namespace
{
cv::Mat randomImage(int type, unsigned seed)
{
	cv::Mat m(37, 53, type);  // odd sizes: no padding hides a wrong step
	cv::theRNG().state = seed;
	cv::randu(m, 0, 256);
	return m;
}

bool samePixels(const cv::Mat& a, const cv::Mat& b)
{
	return a.size() == b.size() && a.type() == b.type() && cv::norm(a, b, cv::NORM_INF) == 0;
}
}  // namespace

TEST(RosConversions, MonoAndBgrImagesRoundTripAndNameTheirEncoding)
{
	for (int type : {CV_8UC1, CV_8UC3})
	{
		const cv::Mat m = randomImage(type, 11 + type);
		const auto msg = mrolr::ros::toImageMsg(mrpt::img::CImage(m, mrpt::img::SHALLOW_COPY), 2.5, "cam");
		EXPECT_EQ(msg.encoding, type == CV_8UC1 ? "mono8" : "bgr8");
		EXPECT_EQ(msg.width, 53u);
		EXPECT_EQ(msg.height, 37u);
		EXPECT_EQ(msg.step, 53u * m.channels());
		EXPECT_EQ(msg.header.frame_id, "cam");
		const auto back = mrolr::ros::fromImageMsg(msg);
		EXPECT_TRUE(samePixels(back.asCvMat<cv::Mat>(mrpt::img::SHALLOW_COPY), m));
	}
}

TEST(RosConversions, AnRgbImageComesBackInOpenCvsOrderAndOtherEncodingsAreNamed)
{
	const cv::Mat bgr = randomImage(CV_8UC3, 5);
	auto msg = mrolr::ros::toImageMsg(mrpt::img::CImage(bgr, mrpt::img::SHALLOW_COPY), 0, "cam");
	for (size_t i = 0; i < msg.data.size(); i += 3) std::swap(msg.data[i], msg.data[i + 2]);
	msg.encoding = "rgb8";
	EXPECT_TRUE(samePixels(mrolr::ros::fromImageMsg(msg).asCvMat<cv::Mat>(mrpt::img::SHALLOW_COPY), bgr));
	msg.encoding = "16UC1";
	try
	{
		mrolr::ros::fromImageMsg(msg);
		ADD_FAILURE() << "16UC1 taken";
	}
	catch (const std::invalid_argument& e)
	{
		EXPECT_NE(std::string(e.what()).find("16UC1"), std::string::npos) << e.what();
	}
	msg.encoding = "bgr8";
	msg.data.resize(10);  // fewer bytes than its size says
	EXPECT_THROW(mrolr::ros::fromImageMsg(msg), std::invalid_argument);
	const cv::Mat shorts(4, 4, CV_16UC1, cv::Scalar(7));
	EXPECT_THROW(mrolr::ros::toImageMsg(mrpt::img::CImage(shorts, mrpt::img::SHALLOW_COPY), 0, "c"),
	             std::invalid_argument);
}

TEST(RosConversions, PosesTransformsAndTimesRoundTrip)
{
	std::mt19937 rng(3);
	std::uniform_real_distribution<> u(-2, 2);
	for (int k = 0; k < 20; ++k)
	{
		Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
		T.linear() = Eigen::Quaterniond(u(rng), u(rng), u(rng), u(rng)).normalized().toRotationMatrix();
		T.translation() = Eigen::Vector3d(u(rng), u(rng), u(rng));
		EXPECT_TRUE(mrolr::ros::fromPoseMsg(mrolr::ros::toPoseMsg(T)).isApprox(T, 1e-12));
		const auto t = mrolr::ros::toTransformMsg(T, "a", "b", 12.25);
		EXPECT_EQ(t.header.frame_id, "a");
		EXPECT_EQ(t.child_frame_id, "b");
		EXPECT_NEAR(t.transform.translation.y, T.translation().y(), 1e-15);
	}
	for (double t : {0.0, 1e-3, 12.345678, 2355.9})
		EXPECT_NEAR(mrolr::ros::fromRosTime(mrolr::ros::toRosTime(t)), t, 1e-6) << "nanosecond stamps";
	geometry_msgs::Pose bad;
	bad.orientation.w = 2;
	EXPECT_THROW(mrolr::ros::fromPoseMsg(bad), std::invalid_argument);
}

TEST(RosConversions, AVehiclePoseIsPlanarInRep103AxesWithItsCovarianceOnXYAndYaw)
{
	const Eigen::Vector3d xv(1.5, -0.25, 0.7);  // z forward, x left, φ from z towards x
	const auto T = mrolr::ros::planarPose(xv);
	const auto m = geometry::vehicleToMrpt(xv);
	EXPECT_NEAR(T.translation().x(), m.x(), 1e-15);
	EXPECT_NEAR(T.translation().y(), m.y(), 1e-15);
	EXPECT_NEAR(T.translation().z(), 0.0, 1e-15);
	EXPECT_NEAR(std::atan2(T(1, 0), T(0, 0)), m.phi(), 1e-12);
	Eigen::Matrix3d P;
	P << 0.04, 0.01, 0.002, 0.01, 0.09, -0.003, 0.002, -0.003, 0.0025;
	const auto c = mrolr::ros::planarCovariance(P, 1e6);
	EXPECT_EQ(mrolr::ros::planarCovarianceFrom(c), P);
	EXPECT_EQ(c[0 * 6 + 5], P(0, 2)) << "x–yaw";
	EXPECT_EQ(c[2 * 6 + 2], 1e6) << "z unobserved";
	const auto odo = mrolr::ros::toOdometryMsg(xv, 4.0);
	EXPECT_EQ(odo.header.frame_id, "odom");
	EXPECT_EQ(odo.child_frame_id, "base_link");
	EXPECT_TRUE(mrolr::ros::fromPoseMsg(odo.pose.pose).isApprox(T, 1e-12));
}
