#pragma once
/** The mission's device factory (DESIGN.md "Plug-ins"): each of base, head and arm is either the
 * simulated lab's own device (`driver = sim`) or a serial driver on the configured port
 * (`driver = serial`, hw_serial/SerialDrivers.h). The mission drives them through the hw::
 * interfaces only. The head's stereo pairs are not on the serial line (docs/serial.md): the serial
 * head grabs them from the lab's renderer (the frame grabber of the simulated robot). When a
 * serial port is not served by the lab's own device (DeviceChoice::lab_behind_port), each command
 * also goes to the lab's device (a shadow), so the simulated perception sees the commanded motion;
 * the replies (odometry, angles, joints) are the serial device's. */
#include <mrolr/hw/Devices.h>
#include <mrolr/mission/DeviceOptions.h>
#include <mrolr/mission/SimulatedLab.h>

#include <memory>
#include <string>
#include <vector>

namespace mrolr::hw
{
class SerialClient;
}

namespace mrolr::mission
{
/** A serial link's counters, for the report. */
struct LinkReport
{
	std::string section, port;
	int resends = 0;  ///< requests that had to be sent again (lost, late or damaged replies)
	bool lab_behind_port = false;  ///< DeviceChoice::lab_behind_port
};

class MissionDevices
{
 public:
	/** Opens every serial port now and checks the device on it (`ID?`); throws util::ConfigError
	 * naming the section's `port` key and the port when it cannot be opened or the device does
	 * not answer, before anything moves. */
	MissionDevices(const DeviceOptions& o, SimulatedLab& lab);
	~MissionDevices();
	hw::BaseDevice& base() { return *base_; }
	hw::HeadDevice& head() { return *head_; }
	hw::ArmDevice& arm() { return *arm_; }
	/** One entry per serial device. */
	std::vector<LinkReport> links() const;

 private:
	std::unique_ptr<hw::SerialClient> open(const DeviceChoice& d);
	void makeBase(const DeviceChoice& d, SimulatedLab& lab);
	void makeHead(const DeviceChoice& d, SimulatedLab& lab);
	void makeArm(const DeviceChoice& d, SimulatedLab& lab);

	struct Link
	{
		std::string section, port;
		const hw::SerialClient* client;
		bool lab_behind_port;
	};
	std::vector<Link> links_;
	std::unique_ptr<hw::BaseDevice> own_base_;
	std::unique_ptr<hw::HeadDevice> own_head_;
	std::unique_ptr<hw::ArmDevice> own_arm_;
	hw::BaseDevice* base_ = nullptr;
	hw::HeadDevice* head_ = nullptr;
	hw::ArmDevice* arm_ = nullptr;
};

}  // namespace mrolr::mission
