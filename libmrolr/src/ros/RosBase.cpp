// The base over topics (RosDevices.h): a wheel step as a JointTrajectory, odometry back.
#include "DeviceLink.h"

#include <mrolr/ros/Conversions.h>
#include <mrolr/ros/DeviceTopics.h>
#include <mrolr/ros/RosDevices.h>

#include <sensor_msgs/JointState.h>
#include <std_msgs/Bool.h>
#include <std_msgs/Float64.h>
#include <trajectory_msgs/JointTrajectory.h>

#include <cmath>

namespace mrolr::ros
{
namespace
{
/** The base's joints: the wheels' encoders, then the dead reckoning (DeviceTopics.h). */
std::vector<std::string> jointNames()
{
	std::vector<std::string> n(topics::kWheelJoints.begin(), topics::kWheelJoints.end());
	n.insert(n.end(), topics::kOdomJoints.begin(), topics::kOdomJoints.end());
	return n;
}
const std::vector<std::string> kNames = jointNames();
}  // namespace

struct RosBase::Replies
{
	::ros::Publisher command;
	std::shared_ptr<Latest<sensor_msgs::JointState>> joints;
	std::shared_ptr<Latest<std_msgs::Bool>> bumper;
	std::shared_ptr<Latest<std_msgs::Float64>> clock;
};

RosBase::RosBase(const ::ros::NodeHandle& nh, const RosDeviceOptions& o)
    : link_(std::make_unique<DeviceLink>(nh, "device.base", o.timeout_ms)),
      replies_(std::make_unique<Replies>())
{
	replies_->command = link_->command<trajectory_msgs::JointTrajectory>(topics::kBaseCommand);
	replies_->joints = link_->reply<sensor_msgs::JointState>(topics::kBaseJoints);
	replies_->bumper = link_->reply<std_msgs::Bool>(topics::kBumper);
	replies_->clock = link_->reply<std_msgs::Float64>(topics::kBaseClock);
	link_->faults(topics::kBaseFault);
	link_->awaitPeers(o.connect_timeout_ms);
	request(nullptr, "state request");
}

RosBase::~RosBase() = default;

void RosBase::request(const base::WheelControl* u, const std::string& what)
{
	trajectory_msgs::JointTrajectory cmd;
	cmd.joint_names.assign(topics::kWheelJoints.begin(), topics::kWheelJoints.end());
	if (u)
	{
		trajectory_msgs::JointTrajectoryPoint p;
		p.velocities = {u->v1_mps, u->v2_mps};
		p.time_from_start = ::ros::Duration(u->dt_s);  // for the tools: nanoseconds
		p.effort = {u->dt_s};                          // for the base: the step exactly
		cmd.points.push_back(p);
	}
	const int step_ms = u ? int(std::ceil(u->dt_s * 1000)) : 0;
	const auto fault = link_->call([&] { replies_->command.publish(cmd); }, what, step_ms);
	if (fault) throw hw::DeviceFailure("device.base over ROS: " + what + ": " + fault->what);
	try
	{
		const auto v = jointPositions(*replies_->joints->msg, kNames);
		odometry_.ticks_right = std::lround(v[0]);
		odometry_.ticks_left = std::lround(v[1]);
		odometry_.xv_zxphi = Eigen::Vector3d(v[2], v[3], v[4]);
		odometry_.time_s = replies_->clock->msg->data;
		odometry_.bumper = replies_->bumper->msg->data;
	}
	catch (const std::invalid_argument& e)
	{
		throw hw::DeviceFailure("device.base over ROS: " + what + ": malformed reply on " +
		                        topics::kBaseJoints + ": " + e.what());
	}
}

void RosBase::step(const base::WheelControl& u)
{
	request(&u, "step");
}

}  // namespace mrolr::ros
