#pragma once
/** A ROS master of one's own: `rosmaster --core` (Debian's python3-rosmaster) on a free port of
 * 127.0.0.1, started by the constructor, which waits until it accepts connections (throws
 * std::runtime_error naming what failed), and stopped by the destructor. It sets ROS_MASTER_URI
 * and ROS_IP for this process and its children, so nothing leaves the machine. For tests,
 * benchmarks and one-command runs. */
#include <string>

#include <sys/types.h>

namespace mrolr::ros
{
class LoopbackMaster
{
 public:
	LoopbackMaster();
	~LoopbackMaster();
	LoopbackMaster(const LoopbackMaster&) = delete;
	LoopbackMaster& operator=(const LoopbackMaster&) = delete;
	/** `http://127.0.0.1:PORT`. */
	const std::string& uri() const { return uri_; }

 private:
	bool accepts() const;
	int port_;
	pid_t pid_ = -1;
	std::string uri_;
};

}  // namespace mrolr::ros
