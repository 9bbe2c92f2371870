#pragma once
/** `mrolr-rawlog2bag`: an MROLR rawlog as a ROS 1 bag (docs/ros.md "Bags from rawlogs"):
 *
 *     mrolr-rawlog2bag IN.rawlog OUT.bag [--json] [--quiet]
 *
 * IN is a mission's recording (mission.rawlog) or an mrolr-sim one; its images are read from
 * `<IN's stem>_Images/`. OUT gets the stereo pairs with their camera info, the encoders'
 * odometry, the head's joints, tf and, when recorded, the world's truth under /ground_truth
 * (ros/RawlogToBag.h). Prints a progress line and the messages per topic (or them as JSON).
 * Exit 0 on success, 1 for a file that cannot be read or written (named), 2 for bad arguments. */
#include <mrolr/ros/RawlogToBag.h>

#include <iosfwd>
#include <string>
#include <vector>

namespace mrolr::apps
{
class Rawlog2BagApp
{
 public:
	void initialize(const std::vector<std::string>& args);
	int run(std::ostream& out, std::ostream& progress);

	std::string rawlog_path, bag_path;
	bool json = false, quiet = false, help_shown = false;
	ros::BagSummary summary;
};

}  // namespace mrolr::apps
