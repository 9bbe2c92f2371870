#pragma once
/** `mrolr-ros-robot`: the mission as a ROS 1 node (docs/ros.md). The robot side only: it reads the
 * mission file, its calibration, its models and its plan, and drives the devices over their
 * topics (ros/RosDevices.h), served by `mrolr-ros-lab` or by real drivers. It never subscribes to
 * `ground_truth/`.
 *
 *     mrolr-ros-robot [--config config/mission_sim.ini] [--plan P.ini] [--out DIR] [--json]
 *                     [--quiet] [--timeout-ms N] [--motion-timeout-ms N] [--lab-timeout-ms N]
 *                     [--master-timeout-ms N] [__name:=NAME] [__ns:=NS]
 *
 * Publishes its estimate (`mrolr/estimate`, geometry_msgs/PoseWithCovarianceStamped), its tf
 * world → odom and base_link → left_camera → right_camera, the recognised object
 * (`mrolr/object_pose`), its stage (`mrolr/stage`) and at the end its map with the 95 %
 * ellipsoids (`mrolr/map`, visualization_msgs/MarkerArray). Writes report.json, report.md and
 * mission.rawlog (every device call, as mrolr-mission records it; `mrolr-mission --replay` replays
 * it with the run's configuration, kept in DIR/run/) into DIR (default out/<name>-ros-<UTC timestamp>) and prints the mission's summary. Exit 0
 * when the mission succeeded, 3 when it ran and failed (a lab that went silent included: the
 * failure names the device, the topic and the node), 130 / 143 on SIGINT / SIGTERM, 1 for an error
 * before anything moved (no master, no lab, a malformed file), 2 for bad arguments. */
#include <mrolr/mission/Mission.h>

#include <nlohmann/json.hpp>

#include <iosfwd>
#include <string>
#include <vector>

namespace mrolr::apps
{
class RosRobotApp
{
 public:
	/** Parses the arguments ROS left (argv[0] first); throws util::UsageError. */
	void initialize(const std::vector<std::string>& args);
	int run(std::ostream& out, std::ostream& progress);

	std::string config_path = "config/mission_sim.ini";
	std::string plan_path;
	std::string out_dir;
	bool json = false, quiet = false, help_shown = false;
	int timeout_ms = 3000, motion_timeout_ms = 20000, master_timeout_ms = 10000,
	    lab_timeout_ms = 20000;
	std::vector<std::string> command;  ///< the arguments as given (kept in <out>/run/)
	mission::MissionOptions options;
	mission::MissionResult result;
	nlohmann::json report;
};

}  // namespace mrolr::apps
