#pragma once
/** The world side of the devices over ROS 1 (docs/ros.md "Devices over topics"): serves any
 * hw:: devices — the simulated lab's, or real ones behind their drivers — on the topics of
 * ros/DeviceTopics.h. Each command is carried out on the device and answered with one message on
 * every reply topic of that device, the fault last (empty when it went well). What a device throws
 * is sent as its fault: a joint limit (geometry::FixationError, std::out_of_range) as `limit`,
 * hw::ArmBlocked as `blocked`, another std::logic_error as `refused`, anything else as `failed`.
 *
 * The callbacks run on the node's global callback queue: spin it with one thread (ros::spin) and
 * the devices are driven in the order the robot asked, as in process. */
#include <mrolr/hw/Devices.h>

#include <functional>
#include <memory>

namespace ros
{
class NodeHandle;
}

namespace mrolr::ros
{
struct ServedDevices
{
	hw::BaseDevice* base = nullptr;
	hw::HeadDevice* head = nullptr;
	hw::ArmDevice* arm = nullptr;
};

class DeviceServer
{
 public:
	DeviceServer(::ros::NodeHandle& nh, const ServedDevices& d);
	~DeviceServer();
	DeviceServer(const DeviceServer&) = delete;
	DeviceServer& operator=(const DeviceServer&) = delete;
	/** Commands carried out (or refused) so far. */
	size_t commands() const;
	/** Called after each base step, with the base's device time (the lab publishes its truth). */
	std::function<void(double time_s)> after_step;
	/** Called after each stereo pair, with its time (the lab publishes the cameras' info). */
	std::function<void(double time_s)> after_grab;

 private:
	struct Impl;
	std::unique_ptr<Impl> impl_;
};

}  // namespace mrolr::ros
