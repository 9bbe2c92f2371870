// One 640x480 mono stereo pair on loopback: through ROS 1 topics (sensor_msgs/Image, TCPROS,
// another process echoing it back) and through MROLR's camera socket (request, pair, reply), in
// the same run. The ROS figure is a round trip (there and back); half of it is the one-way
// latency per pair. Ratio: ROS round trip / camera socket round trip.
#include <mrolr/hw_serial/CameraServer.h>
#include <mrolr/hw_serial/CameraSocketClient.h>
#include <mrolr/ros/Conversions.h>
#include <mrolr/ros/LoopbackMaster.h>

#include <benchmark/benchmark.h>
#include <ros/ros.h>

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <memory>
#include <opencv2/core.hpp>

using namespace mrolr;

namespace
{
/** A 640x480 grey image of uniform noise (incompressible, like the rendered pairs). */
mrpt::img::CImage noise(unsigned seed)
{
	cv::Mat m(480, 640, CV_8UC1);
	cv::theRNG().state = seed;
	cv::randu(m, 0, 256);
	return mrpt::img::CImage(m, mrpt::img::DEEP_COPY);
}
}  // namespace

namespace
{
/** The other process: echoes /pair/left and /pair/right back on /echo/left and /echo/right. */
[[noreturn]] void echo()
{
	int argc = 0;
	::ros::init(argc, nullptr, "bench_ros_echo", ::ros::init_options::NoSigintHandler);
	::ros::NodeHandle nh;
	auto left = nh.advertise<sensor_msgs::Image>("/echo/left", 2);
	auto right = nh.advertise<sensor_msgs::Image>("/echo/right", 2);
	auto a = nh.subscribe<sensor_msgs::Image>("/pair/left", 2,
	                                          [&](const sensor_msgs::Image::ConstPtr& m) { left.publish(m); });
	auto b = nh.subscribe<sensor_msgs::Image>("/pair/right", 2,
	                                          [&](const sensor_msgs::Image::ConstPtr& m) { right.publish(m); });
	::ros::spin();
	_exit(0);
}
}  // namespace

/** The ROS side, set up once: Google Benchmark calls a benchmark function several times, and
 * roscpp initialises once per process. */
struct RosSide
{
	std::unique_ptr<::ros::NodeHandle> nh;
	::ros::Publisher left, right;
	::ros::Subscriber el, er;
	std::atomic<int> back{0};
	sensor_msgs::Image l, r;
	bool connected() const
	{
		return left.getNumSubscribers() && right.getNumSubscribers() && el.getNumPublishers() &&
		       er.getNumPublishers();
	}
};
RosSide* g_ros = nullptr;

static void BM_RosPairRoundTripOnLoopback(benchmark::State& state)
{
	auto& s = *g_ros;
	if (!s.connected()) state.SkipWithError("the echo node did not connect");
	for (auto _ : state)
	{
		s.back = 0;
		s.left.publish(s.l);
		s.right.publish(s.r);
		const auto end = ::ros::WallTime::now() + ::ros::WallDuration(5);
		while (s.back < 2 && ::ros::WallTime::now() < end) ::ros::spinOnce();
		if (s.back < 2)
		{
			state.SkipWithError("a pair did not come back within 5 s");
			break;
		}
	}
	state.SetBytesProcessed(int64_t(state.iterations()) * 2 * 2 * 640 * 480);
}
BENCHMARK(BM_RosPairRoundTripOnLoopback)->Unit(benchmark::kMillisecond)->UseRealTime();

static void BM_CameraSocketPairRoundTrip(benchmark::State& state)
{
	hw::StereoImages pair;
	pair.left = noise(1), pair.right = noise(2);
	hw_serial::CameraServer server([&] { return pair; });
	hw_serial::CameraSocketClient client(server.address(), 5000);
	for (auto _ : state) benchmark::DoNotOptimize(client.grab());
	state.SetBytesProcessed(int64_t(state.iterations()) * 2 * 640 * 480);
}
BENCHMARK(BM_CameraSocketPairRoundTrip)->Unit(benchmark::kMillisecond)->UseRealTime();

int main(int argc, char** argv)
{
	benchmark::Initialize(&argc, argv);
	mrolr::ros::LoopbackMaster master;
	const pid_t child = fork();
	if (child == 0) echo();
	int rargc = 0;
	::ros::init(rargc, nullptr, "bench_ros_transport", ::ros::init_options::NoSigintHandler);
	{
		RosSide s;
		s.nh = std::make_unique<::ros::NodeHandle>();
		s.left = s.nh->advertise<sensor_msgs::Image>("/pair/left", 2);
		s.right = s.nh->advertise<sensor_msgs::Image>("/pair/right", 2);
		auto cb = [&s](const sensor_msgs::Image::ConstPtr&) { ++s.back; };
		s.el = s.nh->subscribe<sensor_msgs::Image>("/echo/left", 2, cb);
		s.er = s.nh->subscribe<sensor_msgs::Image>("/echo/right", 2, cb);
		s.l = mrolr::ros::toImageMsg(noise(1), 0, "left_camera");
		s.r = mrolr::ros::toImageMsg(noise(2), 0, "right_camera");
		for (int i = 0; i < 400 && !s.connected(); ++i)
		{
			::ros::spinOnce();
			::ros::WallDuration(0.025).sleep();
		}
		g_ros = &s;
		benchmark::RunSpecifiedBenchmarks();
		g_ros = nullptr;
	}
	::ros::shutdown();
	kill(child, SIGTERM);
	waitpid(child, nullptr, 0);
	benchmark::Shutdown();
	return 0;
}
