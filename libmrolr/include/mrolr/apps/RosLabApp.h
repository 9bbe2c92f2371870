#pragma once
/** `mrolr-ros-lab`: the simulated lab as a ROS 1 node (docs/ros.md). The world side only: it builds
 * the lab of a world file and serves its base, head, cameras and arm on the device topics
 * (ros/DeviceServer.h); its truth goes to `ground_truth/pose` only, which the robot never reads.
 *
 *     mrolr-ros-lab [--config config/mission_sim.ini] [--world W.ini] [--truth T.rawlog]
 *                   [--master-timeout-ms N] [__name:=NAME] [__ns:=NS]
 *
 * `--config` gives the simulator's sections and `[mission] seed`; `--world` replaces
 * `[simulator] world_file`. Runs until SIGINT or SIGTERM, then writes `--truth` (the true pose
 * after every base step, GROUND_TRUTH records for eval) and prints how many commands it served.
 * Exit 0, 1 for an error (no master, a malformed file), 2 for bad arguments. */
#include <iosfwd>
#include <string>
#include <vector>

namespace mrolr::apps
{
class RosLabApp
{
 public:
	/** Parses the arguments ROS left (argv[0] first); throws util::UsageError. */
	void initialize(const std::vector<std::string>& args);
	int run(std::ostream& out);

	std::string config_path = "config/mission_sim.ini";
	std::string world_path;  ///< empty: [simulator] world_file
	std::string truth_path;  ///< empty: no truth file
	int master_timeout_ms = 10000;
	bool help_shown = false;
	size_t commands = 0;  ///< served, after run()
};

}  // namespace mrolr::apps
