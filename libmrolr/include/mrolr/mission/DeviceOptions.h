#pragma once
/** Sections [device.base], [device.head], [device.arm] and [device.camera] of a mission file:
 * which driver runs each device (DESIGN.md "Plug-ins") and its link. `driver = sim` takes the
 * device the app's simulator provides; `driver = serial` opens the port (`port`, `baud`,
 * `timeout_ms`, `motion_timeout_ms`, `retries`; docs/serial.md). The head's stereo camera is not on
 * the serial line: `[device.camera] driver = sim` (the simulator's head renders the pairs),
 * `socket` (a frame grabber served on `address = 127.0.0.1:PORT`, e.g. by `mrolr-serial
 * emulate`) or `camera_sensor` (two real cameras through MRPT's CCameraSensor, sections
 * [device.camera.left] and [device.camera.right]); absent, the camera is the simulator's. Checked when the mission file is loaded, before anything moves. */
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
	hw_serial::SerialLinkConfig link;  ///< read only when serial
	std::string port_key;       ///< "<file> [section] port", for errors about the port

	/** Reads `driver` (sim | serial; anything else names the choices) and the link keys. */
	void loadFromConfigFile(const mrpt::config::CConfigFileBase& cfg, const std::string& section);
	void dump(std::ostream& out) const;
};

/** The head's stereo camera. */
struct CameraChoice
{
	enum class Driver
	{
		Sim,          ///< the simulator's rendering head
		Socket,       ///< a frame grabber on a local TCP socket (hw_serial::CameraSocketClient)
		CameraSensor  ///< two cameras through mrpt::hwdrivers::CCameraSensor
	};
	Driver driver = Driver::Sim;
	std::string address;   ///< socket: "127.0.0.1:PORT"
	int timeout_ms = 5000;  ///< socket: no pair within this is a timeout
	/** camera_sensor: the sections [device.camera.left] and [device.camera.right] as .ini text
	 * (CCameraSensor's own keys), opened when the devices are built. */
	std::string sensor_sections;
	std::string key;  ///< "<file> [device.camera] driver", for errors
	/** Reads [device.camera] when present; absent, the camera is the simulator's. */
	void loadFromConfigFile(const mrpt::config::CConfigFileBase& cfg);
	void dump(std::ostream& out) const;
};

/** The device sections. */
struct DeviceOptions
{
	DeviceChoice base, head, arm;
	CameraChoice camera;
	void loadFromConfigFile(const mrpt::config::CConfigFileBase& cfg);
	void dump(std::ostream& out) const;
	bool anySerial() const { return base.serial || head.serial || arm.serial; }
	/** True when some device is the simulator's (the app must provide a simulated lab). */
	bool anySim() const
	{
		return !base.serial || !head.serial || !arm.serial ||
		       camera.driver == CameraChoice::Driver::Sim;
	}
};

}  // namespace mrolr::mission
