#pragma once
/** `mrolr-ros-bag`: records a mission's topics into a bag with the C++ rosbag::Bag writer
 * (docs/ros.md), as `rosbag record` would, without needing the rosbag tools:
 *
 *     mrolr-ros-bag --out OUT.bag [--no-compression] [--master-timeout-ms N] [__ns:=NS]
 *
 * Records the device topics (stereo pairs and camera info, odometry, wheel, head and arm joint
 * states, gripper and dock, the commands), /tf, the robot's estimate, map, object pose and stage,
 * and the world's `ground_truth/pose`, each message at its header's time (ROS time now for those
 * without one). Runs until SIGINT or SIGTERM, then closes the bag (a bag is readable only once
 * closed) and prints the message count per topic. LZ4-compressed chunks unless
 * --no-compression. */
#include <iosfwd>
#include <map>
#include <string>
#include <vector>

namespace mrolr::apps
{
class RosBagApp
{
 public:
	void initialize(const std::vector<std::string>& args);
	int run(std::ostream& out);

	std::string bag_path;
	bool compress = true, help_shown = false;
	int master_timeout_ms = 10000;
	std::map<std::string, size_t> counts;  ///< topic → messages written
};

}  // namespace mrolr::apps
