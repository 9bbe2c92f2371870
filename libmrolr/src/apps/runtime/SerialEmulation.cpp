// The simulated lab's devices on pseudo-terminals for the serial end-to-end mission.
#include <mrolr/apps/SerialEmulation.h>

namespace mrolr::apps
{
namespace
{
void useSerial(mission::DeviceChoice& d, const std::string& port, const hw_serial::LinkOptions& defaults)
{
	if (!d.serial)
	{
		d.link.baud = 115200;
		d.link.link = defaults;
	}
	d.serial = true;
	d.link.port = port;
	d.link.link.device = d.section;
	d.port_key = "[" + d.section + "] port (serial emulation)";
}
}  // namespace

SerialEmulation::SerialEmulation(sim::Lab& lab, const hw_serial::FaultOptions& faults)
    : base_handler_(lab.base()), head_handler_(lab.head()), arm_handler_(lab.arm())
{
	base_ = std::make_unique<hw_serial::PtyEmulator>(base_handler_, faults);
	head_ = std::make_unique<hw_serial::PtyEmulator>(head_handler_, faults);
	arm_ = std::make_unique<hw_serial::PtyEmulator>(arm_handler_, faults);
	camera_ = std::make_unique<hw_serial::CameraServer>([&lab] { return lab.head().grab(); });
}

SerialEmulation::~SerialEmulation() = default;

void SerialEmulation::useIn(mission::MissionOptions& o, const hw_serial::LinkOptions& defaults) const
{
	useSerial(o.devices.base, base_->slavePath(), defaults);
	useSerial(o.devices.head, head_->slavePath(), defaults);
	useSerial(o.devices.arm, arm_->slavePath(), defaults);
	o.devices.camera.driver = mission::CameraChoice::Driver::Socket;
	o.devices.camera.address = camera_->address();
	o.devices.camera.key = "[device.camera] driver (serial emulation)";
}

}  // namespace mrolr::apps
