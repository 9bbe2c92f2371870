// The mission's device sections (docs/mission.md "Configuration", docs/serial.md "Config keys").
#include <mrolr/hw_serial/CameraSocketClient.h>
#include <mrolr/mission/DeviceOptions.h>
#include <mrolr/util/Config.h>

#include <ostream>

namespace mrolr::mission
{
void DeviceChoice::loadFromConfigFile(const mrpt::config::CConfigFileBase& cfg,
                                      const std::string& sec)
{
	section = sec;
	const auto driver = util::readString(cfg, section, "driver");
	if (driver != "sim" && driver != "serial")
		throw util::ConfigError(util::describeKey(cfg, section, "driver") + ": '" + driver +
		                        "' is not one of sim, serial");
	serial = driver == "serial";
	port_key = util::describeKey(cfg, section, "port");
	if (serial) link.loadFromConfigFile(cfg, section);
}

void DeviceChoice::dump(std::ostream& out) const
{
	out << "[" << section << "]\ndriver = " << (serial ? "serial" : "sim") << "\n";
	if (serial) link.dump(out);
}

namespace
{
/** [<s>.left] and [<s>.right] as .ini text; either missing is an error naming it. */
std::string sectionsText(const mrpt::config::CConfigFileBase& cfg, const std::string& s)
{
	std::string out;
	for (const std::string side : {".left", ".right"})
	{
		std::vector<std::string> keys;
		cfg.getAllKeys(s + side, keys);
		if (keys.empty())
			throw util::ConfigError(util::describeKey(cfg, s + side, "grabber_type") +
			                        ": missing: driver = camera_sensor needs the section");
		out += "[" + s + side + "]\n";
		for (const auto& k : keys) out += k + " = " + cfg.read_string(s + side, k, "") + "\n";
	}
	return out;
}
}  // namespace

void CameraChoice::loadFromConfigFile(const mrpt::config::CConfigFileBase& cfg)
{
	const std::string s = "device.camera";
	key = util::describeKey(cfg, s, "driver");
	if (!util::hasKey(cfg, s, "driver")) return;
	const auto d = util::readString(cfg, s, "driver");
	if (d == "sim")
		driver = Driver::Sim;
	else if (d == "socket")
		driver = Driver::Socket;
	else if (d == "camera_sensor")
		driver = Driver::CameraSensor;
	else
		throw util::ConfigError(key + ": '" + d + "' is not one of sim, socket, camera_sensor");
	if (driver == Driver::CameraSensor) sensor_sections = sectionsText(cfg, s);
	if (driver != Driver::Socket) return;
	address = util::readString(cfg, s, "address");
	try
	{
		hw_serial::parseCameraAddress(address, s);
	}
	catch (const std::invalid_argument& e)
	{
		throw util::ConfigError(util::describeKey(cfg, s, "address") + ": " + e.what());
	}
	timeout_ms = static_cast<int>(util::readInt(cfg, s, "timeout_ms", timeout_ms));
	util::requireInRange(cfg, s, "timeout_ms", timeout_ms, 10, 600000);
}

void CameraChoice::dump(std::ostream& out) const
{
	const char* names[] = {"sim", "socket", "camera_sensor"};
	out << "[device.camera]\ndriver = " << names[static_cast<int>(driver)] << "\n";
	if (driver == Driver::Socket)
		out << "address = " << address << "\ntimeout_ms = " << timeout_ms << "\n";
}

void DeviceOptions::loadFromConfigFile(const mrpt::config::CConfigFileBase& cfg)
{
	base.loadFromConfigFile(cfg, "device.base");
	head.loadFromConfigFile(cfg, "device.head");
	arm.loadFromConfigFile(cfg, "device.arm");
	camera.loadFromConfigFile(cfg);
}

void DeviceOptions::dump(std::ostream& out) const
{
	for (const auto* d : {&base, &head, &arm})
	{
		d->dump(out);
		out << "\n";
	}
	camera.dump(out);
}

}  // namespace mrolr::mission
