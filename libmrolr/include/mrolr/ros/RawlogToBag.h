#pragma once
/** An MROLR rawlog (a mission's recording or an mrolr-sim one, read by io::readRawlog) as a ROS 1
 * bag, written with rosbag::Bag (docs/ros.md "Bags from rawlogs"). Topics and frames (REP 105):
 *
 * | topic | type | frame |
 * |---|---|---|
 * | /stereo/left/image_raw, /stereo/right/image_raw | sensor_msgs/Image (mono8 or bgr8) | left_camera, right_camera |
 * | /stereo/left/camera_info, /stereo/right/camera_info | sensor_msgs/CameraInfo | the same |
 * | /odom | nav_msgs/Odometry (the encoders' dead reckoning) | odom → base_link |
 * | /head/joint_states | sensor_msgs/JointState: pan, tilt, verg_left, verg_right | — |
 * | /mrolr/estimate | geometry_msgs/PoseWithCovarianceStamped (the robot's, a mission's) | world |
 * | /ground_truth/pose | geometry_msgs/PoseStamped (the world's, when recorded) | world |
 * | /tf | odom → base_link per odometry reading; world → odom per estimate (REP 105: the
 *   estimate's correction of the dead reckoning); base_link → left_camera → right_camera per pair | |
 * | /tf_static | world → odom, when the rawlog holds no estimate | |
 *
 * The camera frames are optical (x right, y down, z forward); base_link is on the ground under
 * the head's centre C0, x forward, y left, z up. */
#include <functional>
#include <map>
#include <string>

namespace mrolr::ros
{
struct BagSummary
{
	size_t records = 0, pairs = 0;
	std::map<std::string, size_t> messages;  ///< topic → messages written
};

/** Converts @p rawlog into a new bag at @p bag (overwritten). @p progress, if set, is called
 * with (records done, records in all). Throws std::runtime_error naming the file that cannot be
 * read or written. */
BagSummary rawlogToBag(const std::string& rawlog, const std::string& bag,
                       const std::function<void(size_t, size_t)>& progress = {});

}  // namespace mrolr::ros
