// Starting and stopping an MROLR node (Node.h).
#include <mrolr/ros/Node.h>

#include <ros/ros.h>

#include <atomic>
#include <chrono>
#include <csignal>
#include <stdexcept>
#include <thread>

namespace mrolr::ros
{
namespace
{
std::atomic<int> g_signal{0};
std::atomic<bool> g_shutdown{true};

extern "C" void onStopSignal(int sig)
{
	g_signal = sig;
	if (g_shutdown) ::ros::requestShutdown();  // what roscpp's own SIGINT handler does
}
}  // namespace

std::vector<std::string> initNode(int argc, char** argv, const std::string& name,
                                  OnStopSignal on_stop)
{
	g_shutdown = on_stop == OnStopSignal::Shutdown;
	::ros::init(argc, argv, name, ::ros::init_options::NoSigintHandler);
	std::signal(SIGINT, onStopSignal);
	std::signal(SIGTERM, onStopSignal);
	return std::vector<std::string>(argv, argv + argc);
}

void waitForMaster(int timeout_ms)
{
	const auto deadline = std::chrono::steady_clock::now() + std::chrono::milliseconds(timeout_ms);
	while (!::ros::master::check())
	{
		if (std::chrono::steady_clock::now() > deadline || g_signal)
			throw std::runtime_error("no ROS master at ROS_MASTER_URI=" + ::ros::master::getURI() +
			                         " within " + std::to_string(timeout_ms) +
			                         " ms (start one with `rosmaster --core`, or use "
			                         "scripts/ros-mission.sh)");
		std::this_thread::sleep_for(std::chrono::milliseconds(100));
	}
}

int shutdownSignal()
{
	return g_signal;
}

}  // namespace mrolr::ros
