#pragma once
/** The robot's devices over ROS 1 topics (docs/ros.md "Devices over topics"): the hw:: interfaces
 * implemented by publishing commands and waiting for the lab's replies (ros/DeviceTopics.h), so
 * the mission runs on them as on the simulator or the serial drivers. Each command's reply carries
 * the device's whole state; the state queries (odometry(), angles(), joints(), …) answer from the
 * last reply. Single-threaded and in order: a call returns only once its replies came.
 *
 * Errors as in process: a joint limit is geometry::FixationError (head) or std::out_of_range
 * (arm), a stalled arm hw::ArmBlocked, a refusal std::logic_error. A reply that does not come in
 * time, or a lab node that is gone, is hw::DeviceFailure naming the device, the silent topics and
 * the node that served them; the mission then stops safely (Mission::run). */
#include <mrolr/hw/Devices.h>

#include <functional>
#include <memory>
#include <string>

namespace ros
{
class NodeHandle;
}

namespace mrolr::ros
{
struct RosDeviceOptions
{
	int timeout_ms = 3000;          ///< a reply beyond the command's own duration
	int motion_timeout_ms = 20000;  ///< head and arm moves, stereo grabs (rendering)
	int connect_timeout_ms = 20000;  ///< waiting for the lab's topics at start
};

class DeviceLink;

class RosBase : public hw::BaseDevice
{
 public:
	RosBase(const ::ros::NodeHandle& nh, const RosDeviceOptions& o);
	~RosBase() override;
	void step(const base::WheelControl& u) override;
	hw::Odometry odometry() const override { return odometry_; }

 private:
	struct Replies;
	void request(const base::WheelControl* u, const std::string& what);
	std::unique_ptr<DeviceLink> link_;
	std::unique_ptr<Replies> replies_;
	hw::Odometry odometry_;
};

class RosHead : public hw::HeadDevice
{
 public:
	RosHead(const ::ros::NodeHandle& nh, const RosDeviceOptions& o);
	~RosHead() override;
	double moveTo(const geometry::HeadAngles& target) override;
	geometry::HeadAngles angles() const override { return angles_; }
	hw::StereoImages grab() override;

 private:
	struct Replies;
	double request(const geometry::HeadAngles* target, const std::string& what);
	std::unique_ptr<DeviceLink> move_link_, grab_link_;
	std::unique_ptr<Replies> replies_;
	geometry::HeadAngles angles_;
	uint64_t frames_ = 0;
};

class RosArm : public hw::ArmDevice
{
 public:
	RosArm(const ::ros::NodeHandle& nh, const RosDeviceOptions& o);
	~RosArm() override;
	void moveTo(const hw::ArmJoints& joints) override;
	hw::ArmJoints joints() const override { return joints_; }
	void setGripper(bool closed) override;
	bool gripperClosed() const override { return closed_; }
	double gripperWidthMm() const override { return width_mm_; }
	void dock(bool docked) override;
	bool docked() const override { return docked_; }

 private:
	struct Replies;
	void call(const std::function<void()>& publish, const std::string& what, int extra_ms);
	void refresh();
	std::unique_ptr<DeviceLink> link_;
	std::unique_ptr<Replies> replies_;
	hw::ArmJoints joints_{};
	bool closed_ = false, docked_ = false;
	double width_mm_ = 0;
};

/** The three devices, connected: each waits for the lab's topics and asks for its state first
 * (throws hw::DeviceFailure naming what is missing when the lab is not there). */
struct RosDevices
{
	RosDevices(const ::ros::NodeHandle& nh, const RosDeviceOptions& o);
	RosBase base;
	RosHead head;
	RosArm arm;
};

}  // namespace mrolr::ros
