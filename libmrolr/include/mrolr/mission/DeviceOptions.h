#pragma once
/** Sections [device.base], [device.head], [device.arm] of a mission file: which driver runs each
 * device (`driver = sim | serial`, DESIGN.md "Plug-ins") and, for `serial`, its link (`port`,
 * `baud`, `timeout_ms`, `motion_timeout_ms`, `retries`; docs/serial.md). Checked when the mission
 * file is loaded, before anything moves. */
#include <mrolr/hw_serial/SerialFactory.h>

#include <mrpt/config/CConfigFileBase.h>

#include <iosfwd>
#include <string>

namespace mrolr::mission
{
/** One device section. */
struct DeviceChoice
{
	std::string section;        ///< "device.base", "device.head" or "device.arm"
	bool serial = false;        ///< driver = serial (else sim)
	hw::SerialLinkConfig link;  ///< read only when serial
	std::string port_key;       ///< "<file> [section] port", for errors about the port
	/** The port is served by an emulator around the SimulatedLab's own device (SerialEmulation).
	 * Otherwise (real hardware, or emulators in another process) every command is also given to
	 * the lab's device, so that the simulated perception follows the commanded motion. */
	bool lab_behind_port = false;

	/** Reads `driver` (sim | serial; anything else names the choices) and the link keys. */
	void loadFromConfigFile(const mrpt::config::CConfigFileBase& cfg, const std::string& section);
	void dump(std::ostream& out) const;
};

/** The three device sections. */
struct DeviceOptions
{
	DeviceChoice base, head, arm;
	void loadFromConfigFile(const mrpt::config::CConfigFileBase& cfg);
	void dump(std::ostream& out) const;
	bool anySerial() const { return base.serial || head.serial || arm.serial; }
};

}  // namespace mrolr::mission
