// The arm, its gripper and its dock over topics (RosDevices.h): joints in SI units on the wire
// (d1 in m, q1..q6 in rad, REP 103), in the thesis's (mm, degrees) at the interface.
#include "DeviceLink.h"

#include <mrolr/ros/Conversions.h>
#include <mrolr/ros/DeviceTopics.h>
#include <mrolr/ros/RosDevices.h>

#include <sensor_msgs/JointState.h>
#include <std_msgs/Bool.h>
#include <trajectory_msgs/JointTrajectory.h>

#include <cmath>

namespace mrolr::ros
{
namespace
{
constexpr double kMPerMm = 1e-3;
constexpr double kRadPerDeg = M_PI / 180.0;

std::vector<std::string> wireNames()
{
	std::vector<std::string> n(topics::kArmJointNames.begin(), topics::kArmJointNames.end());
	n.push_back(topics::kGripperJoint);
	return n;
}
}  // namespace

struct RosArm::Replies
{
	::ros::Publisher command, gripper, dock;
	std::shared_ptr<Latest<sensor_msgs::JointState>> joints;
	std::shared_ptr<Latest<std_msgs::Bool>> closed, docked;
};

RosArm::RosArm(const ::ros::NodeHandle& nh, const RosDeviceOptions& o)
    : link_(std::make_unique<DeviceLink>(nh, "device.arm", o.motion_timeout_ms)),
      replies_(std::make_unique<Replies>())
{
	auto& r = *replies_;
	r.command = link_->command<trajectory_msgs::JointTrajectory>(topics::kArmCommand);
	r.gripper = link_->command<std_msgs::Bool>(topics::kGripperCommand);
	r.dock = link_->command<std_msgs::Bool>(topics::kDockCommand);
	r.joints = link_->reply<sensor_msgs::JointState>(topics::kArmJoints);
	r.closed = link_->reply<std_msgs::Bool>(topics::kGripperClosed);
	r.docked = link_->reply<std_msgs::Bool>(topics::kArmDocked);
	link_->faults(topics::kArmFault);
	link_->awaitPeers(o.connect_timeout_ms);
	refresh();
}

RosArm::~RosArm() = default;

void RosArm::refresh()
{
	trajectory_msgs::JointTrajectory ask;
	ask.joint_names.assign(topics::kArmJointNames.begin(), topics::kArmJointNames.end());
	call([&] { replies_->command.publish(ask); }, "state request", 0);
}

void RosArm::call(const std::function<void()>& publish, const std::string& what, int extra_ms)
{
	const auto fault = link_->call(publish, what, extra_ms);
	if (fault)
	{
		refresh();  // where it stopped (a stalled or refused arm stays where it is)
		if (fault->kind == topics::kLimit) throw std::out_of_range(fault->what);
		if (fault->kind == topics::kBlocked) throw hw::ArmBlocked(fault->what);
		if (fault->kind == topics::kRefused) throw std::logic_error(fault->what);
		throw hw::DeviceFailure("device.arm over ROS: " + what + ": " + fault->what);
	}
	try
	{
		const auto v = jointPositions(*replies_->joints->msg, wireNames());
		joints_[0] = v[0] / kMPerMm;
		for (size_t i = 1; i < 7; ++i) joints_[i] = v[i] / kRadPerDeg;
		width_mm_ = v[7] / kMPerMm;
	}
	catch (const std::invalid_argument& e)
	{
		throw hw::DeviceFailure("device.arm over ROS: malformed " + topics::kArmJoints + ": " +
		                        e.what());
	}
	closed_ = replies_->closed->msg->data;
	docked_ = replies_->docked->msg->data;
}

void RosArm::moveTo(const hw::ArmJoints& j)
{
	trajectory_msgs::JointTrajectory cmd;
	cmd.joint_names.assign(topics::kArmJointNames.begin(), topics::kArmJointNames.end());
	trajectory_msgs::JointTrajectoryPoint p;
	p.positions.push_back(j[0] * kMPerMm);
	for (size_t i = 1; i < 7; ++i) p.positions.push_back(j[i] * kRadPerDeg);
	cmd.points.push_back(p);
	call([&] { replies_->command.publish(cmd); }, "move", 0);
}

void RosArm::setGripper(bool closed)
{
	std_msgs::Bool b;
	b.data = closed;
	call([&] { replies_->gripper.publish(b); }, closed ? "close gripper" : "open gripper", 0);
}

void RosArm::dock(bool docked)
{
	std_msgs::Bool b;
	b.data = docked;
	call([&] { replies_->dock.publish(b); }, docked ? "dock" : "de-couple", 0);
}

RosDevices::RosDevices(const ::ros::NodeHandle& nh, const RosDeviceOptions& o)
    : base(nh, o), head(nh, o), arm(nh, o)
{
}

}  // namespace mrolr::ros
