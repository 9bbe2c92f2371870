#pragma once
/** The serial half of the device factory: builds a serial driver from a device section of the
 * mission config (config/mission_hw.ini), e.g.
 *
 *     [device.base]
 *     driver = serial
 *     port = /dev/ttyUSB0
 *     baud = 9600
 *     timeout_ms = 500
 *     motion_timeout_ms = 5000
 *     retries = 3
 *
 * The choice between `sim` and `serial` is the mission's factory; these functions do not read
 * `driver`. */

#include <mrolr/hw_serial/SerialClient.h>
#include <mrolr/hw_serial/SerialDrivers.h>

#include <mrpt/config/CConfigFileBase.h>

#include <iosfwd>
#include <memory>

namespace mrolr::hw_serial
{
/** Keys `port`, `baud` (required), `timeout_ms`, `motion_timeout_ms`, `retries` (optional) of a
 * device section. A STEP waits timeout_ms plus its dt; a head or arm MOVE waits motion_timeout_ms.
 */
struct SerialLinkConfig
{
	std::string port;
	int baud = 9600;
	LinkOptions link;  ///< link.device is the section name

	void loadFromConfigFile(const mrpt::config::CConfigFileBase& cfg, const std::string& section);
	void dump(std::ostream& out) const;
};

/** Opens the port (mrpt::comms::CSerialPort) and returns a client; throws SerialDeviceError
 * (Disconnected) naming the section and port when it cannot be opened. */
std::unique_ptr<SerialClient> openSerialClient(const SerialLinkConfig& config);

std::unique_ptr<hw::BaseDevice> makeSerialBaseDevice(const mrpt::config::CConfigFileBase& cfg,
                                                 const std::string& section);
std::unique_ptr<hw::HeadDevice> makeSerialHeadDevice(const mrpt::config::CConfigFileBase& cfg,
                                                 const std::string& section, ImageSource images);
std::unique_ptr<hw::ArmDevice> makeSerialArmDevice(const mrpt::config::CConfigFileBase& cfg,
                                               const std::string& section);

}  // namespace mrolr::hw_serial
