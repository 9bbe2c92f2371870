#pragma once
/** Starting and stopping an MROLR node (mrolr-ros-lab, mrolr-ros-robot): ROS's own arguments
 * (`__name:=`, `__ns:=`, remappings) are taken by ros::init, SIGINT and SIGTERM request a clean
 * shutdown (the bag and the recordings are closed, nothing recorded is lost), and a master that
 * cannot be reached is an error naming ROS_MASTER_URI instead of roscpp's endless retries. */
#include <string>
#include <vector>

namespace mrolr::ros
{
/** What SIGINT and SIGTERM do. */
enum class OnStopSignal
{
	Shutdown,  ///< ros::requestShutdown(): ros::spin() returns (the lab)
	FlagOnly   ///< only shutdownSignal() tells: the robot stops its mission safely first, with
	           ///< its topics still up to send the stop
};

/** ros::init on @p argc / @p argv as node @p name; returns the arguments ROS did not take
 * (argv[0] first). */
std::vector<std::string> initNode(int argc, char** argv, const std::string& name,
                                  OnStopSignal on_stop = OnStopSignal::Shutdown);

/** Waits up to @p timeout_ms for the master; throws std::runtime_error naming ROS_MASTER_URI. */
void waitForMaster(int timeout_ms);

/** The signal that asked for the shutdown, 0 if none. */
int shutdownSignal();

}  // namespace mrolr::ros
