// A ROS master on a free loopback port (LoopbackMaster.h).
#include <mrolr/ros/LoopbackMaster.h>

#include <arpa/inet.h>
#include <netinet/in.h>
#include <signal.h>
#include <spawn.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <stdexcept>
#include <thread>

extern char** environ;

namespace mrolr::ros
{
namespace
{
sockaddr_in loopback(int port)
{
	sockaddr_in a{};
	a.sin_family = AF_INET;
	a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
	a.sin_port = htons(static_cast<uint16_t>(port));
	return a;
}

int freePort()
{
	const int s = socket(AF_INET, SOCK_STREAM, 0);
	sockaddr_in a = loopback(0);
	socklen_t n = sizeof(a);
	const bool ok = bind(s, reinterpret_cast<sockaddr*>(&a), sizeof(a)) == 0 &&
	                getsockname(s, reinterpret_cast<sockaddr*>(&a), &n) == 0;
	close(s);
	if (!ok) throw std::runtime_error("no free port on 127.0.0.1 for a ROS master");
	return ntohs(a.sin_port);
}
}  // namespace

LoopbackMaster::LoopbackMaster() : port_(freePort())
{
	uri_ = "http://127.0.0.1:" + std::to_string(port_);
	setenv("ROS_MASTER_URI", uri_.c_str(), 1);
	setenv("ROS_IP", "127.0.0.1", 1);
	const std::string port = std::to_string(port_);
	const char* argv[] = {"/usr/bin/rosmaster", "--core", "-p", port.c_str(), nullptr};
	if (posix_spawn(&pid_, argv[0], nullptr, nullptr, const_cast<char**>(argv), environ) != 0)
		throw std::runtime_error("cannot start /usr/bin/rosmaster (run scripts/install-deps.sh)");
	const auto end = std::chrono::steady_clock::now() + std::chrono::seconds(20);
	while (!accepts() && std::chrono::steady_clock::now() < end)
		std::this_thread::sleep_for(std::chrono::milliseconds(50));
	if (!accepts())
	{
		kill(pid_, SIGKILL);
		waitpid(pid_, nullptr, 0);
		throw std::runtime_error("the ROS master on " + uri_ + " did not start within 20 s");
	}
}

LoopbackMaster::~LoopbackMaster()
{
	kill(pid_, SIGTERM);
	for (int i = 0; i < 60; ++i)
	{
		if (waitpid(pid_, nullptr, WNOHANG) == pid_) return;
		std::this_thread::sleep_for(std::chrono::milliseconds(50));
	}
	kill(pid_, SIGKILL);
	waitpid(pid_, nullptr, 0);
}

bool LoopbackMaster::accepts() const
{
	const int s = socket(AF_INET, SOCK_STREAM, 0);
	const sockaddr_in a = loopback(port_);
	const bool ok = connect(s, reinterpret_cast<const sockaddr*>(&a), sizeof(a)) == 0;
	close(s);
	return ok;
}

}  // namespace mrolr::ros
