#pragma once
/** MROLR's data as standard ROS 1 messages and back (docs/ros.md). Frames follow REP 103/105:
 * x forward, y left, z up, which are MRPT's axes; a thesis vehicle pose (z, x, φ) in W becomes
 * (x = z, y = x, yaw = φ) in `world` (geometry::vehicleToMrpt). Times are MROLR's seconds from the
 * start of a run, carried as ROS time 1.7e9 s + t as in the rawlogs (io/Rawlog.h).
 *
 * Images are converted here, not by MRPT 2.5.8's ros1bridge, whose image conversion labels every
 * image `bgr8` (mono ones included) and whose stereo conversion fills the right message from the
 * left image. */
#include <mrolr/io/Rawlog.h>

#include <mrpt/img/CImage.h>
#include <mrpt/img/TCamera.h>

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <geometry_msgs/Pose.h>
#include <geometry_msgs/PoseWithCovariance.h>
#include <geometry_msgs/TransformStamped.h>
#include <nav_msgs/Odometry.h>
#include <ros/time.h>
#include <sensor_msgs/CameraInfo.h>
#include <sensor_msgs/Image.h>
#include <sensor_msgs/JointState.h>

#include <string>
#include <vector>

namespace mrolr::ros
{
/** ROS time io::kTimeOffset_s + t, as the rawlogs stamp it (ROS time 0 is "no time"), to the
 * nanosecond. */
::ros::Time toRosTime(double time_s);
double fromRosTime(const ::ros::Time& t);
/** A duration in seconds as sec + nsec / 1e9 (a division, so a duration given with up to nine
 * decimals, such as 0.1 s, comes back as the same double; ros::Duration::toSec multiplies by
 * 1e-9 and gives 0.30000000000000004 for 0.3). */
double secondsOf(const ::ros::Duration& d);

/** An 8-bit image: `mono8` with one channel, `bgr8` with three (OpenCV's order). Throws
 * std::invalid_argument for any other depth or channel count. */
sensor_msgs::Image toImageMsg(const mrpt::img::CImage& img, double time_s,
                              const std::string& frame_id);
/** The pixels of @p m: `mono8`, `bgr8` and `rgb8` (turned to BGR); throws std::invalid_argument
 * naming any other encoding, or a size that does not match the data. */
mrpt::img::CImage fromImageMsg(const sensor_msgs::Image& m);

/** A distortion-free pinhole camera (intrinsics in pixels) as sensor_msgs/CameraInfo
 * (`plumb_bob` with zero coefficients). */
sensor_msgs::CameraInfo toCameraInfo(const mrpt::img::TCamera& cam, double time_s,
                                     const std::string& frame_id);

geometry_msgs::Pose toPoseMsg(const Eigen::Isometry3d& T);
Eigen::Isometry3d fromPoseMsg(const geometry_msgs::Pose& p);
geometry_msgs::TransformStamped toTransformMsg(const Eigen::Isometry3d& T_childInParent,
                                               const std::string& parent,
                                               const std::string& child, double time_s);

/** A vehicle pose (z, x, φ) in W as a planar pose in `frame`, x = z, y = x, yaw = φ. */
Eigen::Isometry3d planarPose(const Eigen::Vector3d& xv_zxphi);
/** The vehicle pose (z, x, φ) of a planar pose (x, y, yaw; roll and pitch ignored): the inverse
 * of planarPose, φ wrapped to (−π, π]. */
Eigen::Vector3d planarPoseFrom(const geometry_msgs::Pose& p);
/** Its covariance (P_vv over z, x, φ) in ROS's row-major 6×6 over (x, y, z, roll, pitch, yaw);
 * the three unobserved axes get @p unobserved_var. */
boost::array<double, 36> planarCovariance(const Eigen::Matrix3d& P_vv,
                                          double unobserved_var = 0.0);
/** The 3×3 over (x, y, yaw) of a ROS 6×6 covariance: the inverse of planarCovariance. */
Eigen::Matrix3d planarCovarianceFrom(const boost::array<double, 36>& cov);

/** Encoder odometry: the dead-reckoned pose (z, x, φ) in `odom`, child `base_link`. */
nav_msgs::Odometry toOdometryMsg(const Eigen::Vector3d& xv_zxphi, double time_s);

/** The head's joints as sensor_msgs/JointState: `pan`, `tilt`, `verg_left`, `verg_right` (rad). */
sensor_msgs::JointState headJointsMsg(const Eigen::Vector4d& head_rad, double time_s);

/** The positions of the joints @p names in @p m, in that order; throws std::invalid_argument
 * naming a joint that is missing or a message whose arrays disagree in length. */
std::vector<double> jointPositions(const sensor_msgs::JointState& m,
                                   const std::vector<std::string>& names);

}  // namespace mrolr::ros
