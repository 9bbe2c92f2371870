#pragma once
/** The robot's device factory (DESIGN.md "Plug-ins"): each of base, head and arm is either the
 * simulator's own device (`driver = sim`, given by the app that runs a simulator) or a serial
 * driver on the configured port (`driver = serial`, hw_serial/SerialDrivers.h); the head's stereo
 * pairs come from its camera (`[device.camera]`: the simulator's, a frame grabber on a local
 * socket, or real cameras). Through a port the robot has only what the port and the camera give
 * it. The mission drives them through the hw:: interfaces only. */
#include <mrolr/hw/Devices.h>
#include <mrolr/mission/DeviceOptions.h>
#include <mrolr/mission/Mission.h>

#include <memory>
#include <string>
#include <vector>

namespace mrolr::hw_serial
{
class SerialClient;
}

namespace mrolr::mission
{
/** The simulator's devices, for sections with `driver = sim` (any may be null without one). */
struct SimDevices
{
	hw::BaseDevice* base = nullptr;
	hw::HeadDevice* head = nullptr;
	hw::ArmDevice* arm = nullptr;
};

class MissionDevices
{
 public:
	/** Opens every serial port and the camera now and checks the device on it (`ID?`); throws
	 * util::ConfigError naming the key (the port, the camera, or a `driver = sim` without a
	 * simulator) before anything moves. */
	MissionDevices(const DeviceOptions& o, const SimDevices& sim);
	~MissionDevices();
	RobotDevices devices();
	/** One entry per serial device. */
	std::vector<LinkReport> links() const;

 private:
	std::unique_ptr<hw_serial::SerialClient> open(const DeviceChoice& d);
	hw_serial::ImageSource camera(const DeviceOptions& o, const SimDevices& sim);

	struct Link
	{
		std::string section, port;
		const hw_serial::SerialClient* client;
	};
	std::vector<Link> links_;
	std::shared_ptr<void> camera_;  ///< the camera behind the serial head's image source
	std::unique_ptr<hw::BaseDevice> own_base_;
	std::unique_ptr<hw::HeadDevice> own_head_;
	std::unique_ptr<hw::ArmDevice> own_arm_;
	hw::BaseDevice* base_ = nullptr;
	hw::HeadDevice* head_ = nullptr;
	hw::ArmDevice* arm_ = nullptr;
};

}  // namespace mrolr::mission
