#pragma once
/** The topics and joint names of MROLR's devices on ROS 1 (docs/ros.md "Devices over topics"),
 * one place for both sides: the lab node serves the hw:: devices on them (ros/DeviceServer.h),
 * the robot node drives them (ros/RosDevices.h). Names are relative, so a namespace given to a
 * node (`__ns:=`) moves all of them; the defaults follow REP 103/105 and the usual driver names
 * (`odom`, `stereo/left/image_raw`). Standard messages only:
 *
 * | device | command (robot → lab) | replies (lab → robot, one of each per command) |
 * |---|---|---|
 * | base | `base/command` trajectory_msgs/JointTrajectory: wheel_right, wheel_left velocities (m/s), time_from_start = the step for the tools (nanoseconds), the point's one `effort` value = the step in s exactly (without it, time_from_start is used) | `base/joint_states` sensor_msgs/JointState (wheel_right, wheel_left: encoder ticks; odom_x, odom_y, odom_yaw: the dead-reckoned pose as a planar virtual joint, m and rad, the yaw not wrapped), `base/bumper` std_msgs/Bool, `base/clock` std_msgs/Float64 (the base's time, s), `base/fault`; and `odom` nav_msgs/Odometry for the tools |
 * | head | `head/command` JointTrajectory: pan, tilt, verg_left, verg_right (rad) | `head/joint_states` JointState, `head/settle_time` std_msgs/Float64 (s), `head/fault` |
 * | cameras | `stereo/trigger` std_msgs/Empty | `stereo/left/image_raw`, `stereo/right/image_raw` sensor_msgs/Image, `head/joint_states` (the angles at the grab), `stereo/clock` std_msgs/Float64 (the grab's time, s), `stereo/fault`; and `stereo/left/camera_info`, `stereo/right/camera_info` |
 * | arm | `arm/command` JointTrajectory: d1 (m), q1..q6 (rad); `gripper/command` std_msgs/Bool (true: close); `arm/dock` std_msgs/Bool (true: dock) | `arm/joint_states` JointState (d1..q6 and `gripper`, the jaw opening in m), `gripper/closed` std_msgs/Bool, `arm/docked` std_msgs/Bool, `arm/fault` |
 *
 * Every number the robot computes with crosses in a float64 field, so it arrives as the device
 * sent it (ROS time in the headers has nanoseconds only, a quaternion's yaw is wrapped and rounded:
 * those serve the tools). A command with no trajectory point asks for the device's state only. Every `<device>/fault` is a
 * std_msgs/String, sent last: empty when the command was carried out; otherwise
 * `KIND: what`, KIND one of `limit`, `blocked`, `refused`, `failed`, and then no other reply.
 * The world's truth is published under `ground_truth/` only, which the robot never subscribes to.
 */
#include <array>
#include <string>

namespace mrolr::ros::topics
{
/** Outgoing queue of every topic MROLR's nodes publish, per subscriber. The robot takes each of
 * the lab's replies before its next command, but a recorder (mrolr-ros-bag) compressing images on a
 * busy machine can lag behind by dozens of pairs; roscpp drops the oldest message past this depth,
 * so it is deep enough that a bag never loses one (a full queue of images is about 256 MB, held
 * only while a recorder lags). */
inline constexpr unsigned kPublisherQueue = 256;
/** Incoming queue of each topic a recorder subscribes to, for the same reason. */
inline constexpr unsigned kRecorderQueue = 1024;

inline const std::string kBaseCommand = "base/command";
inline const std::string kOdom = "odom";
inline const std::string kBaseJoints = "base/joint_states";
inline const std::string kBaseClock = "base/clock";
inline const std::string kBumper = "base/bumper";
inline const std::string kBaseFault = "base/fault";

inline const std::string kHeadCommand = "head/command";
inline const std::string kHeadJoints = "head/joint_states";
inline const std::string kHeadSettle = "head/settle_time";
inline const std::string kHeadFault = "head/fault";

inline const std::string kStereoTrigger = "stereo/trigger";
inline const std::string kLeftImage = "stereo/left/image_raw";
inline const std::string kRightImage = "stereo/right/image_raw";
inline const std::string kLeftInfo = "stereo/left/camera_info";
inline const std::string kRightInfo = "stereo/right/camera_info";
inline const std::string kStereoClock = "stereo/clock";
inline const std::string kStereoFault = "stereo/fault";

inline const std::string kArmCommand = "arm/command";
inline const std::string kGripperCommand = "gripper/command";
inline const std::string kDockCommand = "arm/dock";
inline const std::string kArmJoints = "arm/joint_states";
inline const std::string kGripperClosed = "gripper/closed";
inline const std::string kArmDocked = "arm/docked";
inline const std::string kArmFault = "arm/fault";

/** The robot's own view (mrolr-ros-robot). */
inline const std::string kEstimate = "mrolr/estimate";
inline const std::string kPath = "mrolr/path";
inline const std::string kMap = "mrolr/map";
inline const std::string kObjectPose = "mrolr/object_pose";
inline const std::string kStage = "mrolr/stage";

/** The world's truth (mrolr-ros-lab), never read by the robot. */
inline const std::string kTruthPrefix = "ground_truth/";
inline const std::string kTruthPose = "ground_truth/pose";

inline const std::array<std::string, 2> kWheelJoints{"wheel_right", "wheel_left"};
inline const std::array<std::string, 3> kOdomJoints{"odom_x", "odom_y", "odom_yaw"};
inline const std::array<std::string, 4> kHeadJointNames{"pan", "tilt", "verg_left", "verg_right"};
inline const std::array<std::string, 7> kArmJointNames{"d1", "q1", "q2", "q3", "q4", "q5", "q6"};
inline const std::string kGripperJoint = "gripper";

/** Fault kinds on the `<device>/fault` topics. */
inline const std::string kLimit = "limit";
inline const std::string kBlocked = "blocked";
inline const std::string kRefused = "refused";
inline const std::string kFailed = "failed";

}  // namespace mrolr::ros::topics
