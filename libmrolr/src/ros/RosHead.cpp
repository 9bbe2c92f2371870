// The head and its cameras over topics (RosDevices.h): joint moves as a JointTrajectory, stereo
// pairs on a trigger.
#include "DeviceLink.h"

#include <mrolr/geometry/GeometryError.h>
#include <mrolr/ros/Conversions.h>
#include <mrolr/ros/DeviceTopics.h>
#include <mrolr/ros/RosDevices.h>

#include <sensor_msgs/Image.h>
#include <sensor_msgs/JointState.h>
#include <std_msgs/Empty.h>
#include <std_msgs/Float64.h>
#include <trajectory_msgs/JointTrajectory.h>

namespace mrolr::ros
{
namespace
{
const std::vector<std::string> kNames(topics::kHeadJointNames.begin(),
                                      topics::kHeadJointNames.end());

geometry::HeadAngles anglesOf(const sensor_msgs::JointState& m)
{
	const auto v = jointPositions(m, kNames);
	return {v[0], v[1], v[2], v[3]};
}
}  // namespace

struct RosHead::Replies
{
	::ros::Publisher command, trigger;
	std::shared_ptr<Latest<sensor_msgs::JointState>> joints, grab_joints;
	std::shared_ptr<Latest<std_msgs::Float64>> settle, clock;
	std::shared_ptr<Latest<sensor_msgs::Image>> left, right;
};

RosHead::RosHead(const ::ros::NodeHandle& nh, const RosDeviceOptions& o)
    : move_link_(std::make_unique<DeviceLink>(nh, "device.head", o.motion_timeout_ms)),
      grab_link_(std::make_unique<DeviceLink>(nh, "device.camera", o.motion_timeout_ms)),
      replies_(std::make_unique<Replies>())
{
	auto& r = *replies_;
	r.command = move_link_->command<trajectory_msgs::JointTrajectory>(topics::kHeadCommand);
	r.joints = move_link_->reply<sensor_msgs::JointState>(topics::kHeadJoints);
	r.settle = move_link_->reply<std_msgs::Float64>(topics::kHeadSettle);
	move_link_->faults(topics::kHeadFault);
	r.trigger = grab_link_->command<std_msgs::Empty>(topics::kStereoTrigger);
	r.left = grab_link_->reply<sensor_msgs::Image>(topics::kLeftImage);
	r.right = grab_link_->reply<sensor_msgs::Image>(topics::kRightImage);
	r.grab_joints = grab_link_->reply<sensor_msgs::JointState>(topics::kHeadJoints);
	r.clock = grab_link_->reply<std_msgs::Float64>(topics::kStereoClock);
	grab_link_->faults(topics::kStereoFault);
	move_link_->awaitPeers(o.connect_timeout_ms);
	grab_link_->awaitPeers(o.connect_timeout_ms);
	request(nullptr, "state request");
}

RosHead::~RosHead() = default;

double RosHead::request(const geometry::HeadAngles* t, const std::string& what)
{
	trajectory_msgs::JointTrajectory cmd;
	cmd.joint_names = kNames;
	if (t)
	{
		trajectory_msgs::JointTrajectoryPoint p;
		p.positions = {t->pan, t->tilt, t->verg_left, t->verg_right};
		cmd.points.push_back(p);
	}
	const auto fault = move_link_->call([&] { replies_->command.publish(cmd); }, what);
	if (fault && fault->kind == topics::kLimit) throw geometry::FixationError(fault->what);
	if (fault) throw hw::DeviceFailure("device.head over ROS: " + what + ": " + fault->what);
	try
	{
		angles_ = anglesOf(*replies_->joints->msg);
	}
	catch (const std::invalid_argument& e)
	{
		throw hw::DeviceFailure("device.head over ROS: malformed " + topics::kHeadJoints + ": " +
		                        e.what());
	}
	return replies_->settle->msg->data;
}

double RosHead::moveTo(const geometry::HeadAngles& target)
{
	return request(&target, "move");
}

hw::StereoImages RosHead::grab()
{
	const auto fault = grab_link_->call([&] { replies_->trigger.publish(std_msgs::Empty()); }, "grab");
	if (fault) throw hw::DeviceFailure("device.camera over ROS: grab: " + fault->what);
	hw::StereoImages pair;
	try
	{
		pair.left = fromImageMsg(*replies_->left->msg);
		pair.right = fromImageMsg(*replies_->right->msg);
		pair.angles = anglesOf(*replies_->grab_joints->msg);
	}
	catch (const std::invalid_argument& e)
	{
		throw hw::DeviceFailure(std::string("device.camera over ROS: malformed pair: ") + e.what());
	}
	pair.time_s = replies_->clock->msg->data;
	pair.frame = frames_++;
	return pair;
}

}  // namespace mrolr::ros
