// The mission's device sections (docs/mission.md "Configuration", docs/serial.md "Config keys").
#include <mrolr/hw_serial/CameraSocketClient.h>
#include <mrolr/mission/DeviceOptions.h>
#include <mrolr/util/OptionsBinder.h>

#include <ostream>

namespace mrolr::mission
{
namespace
{
const util::OptionsBinder<DeviceChoice>& deviceBinder()
{
	static const auto b = util::OptionsBinder<DeviceChoice>().choice(
	    "driver", &DeviceChoice::serial, util::ChoiceNames<bool>{{"sim", false}, {"serial", true}});
	return b;
}

using C = CameraChoice;

/** [device.camera]: absent, the camera is the simulator's. */
const util::OptionsBinder<C>& cameraBinder()
{
	static const auto b = util::OptionsBinder<C>().choice(
	    "driver", &C::driver,
	    util::ChoiceNames<C::Driver>{{"sim", C::Driver::Sim},
	                                 {"socket", C::Driver::Socket},
	                                 {"camera_sensor", C::Driver::CameraSensor}},
	    util::Presence::Optional);
	return b;
}

/** driver = socket: where the frame grabber listens, and how long a pair may take. */
const util::OptionsBinder<C>& socketBinder()
{
	static const auto b = util::OptionsBinder<C>()
	                          .text("address", &C::address)
	                          .integer("timeout_ms", &C::timeout_ms, 10, 600000,
	                                   util::Presence::Optional);
	return b;
}
}  // namespace

void DeviceChoice::loadFromConfigFile(const mrpt::config::CConfigFileBase& cfg,
                                      const std::string& sec)
{
	section = sec;
	deviceBinder().load(cfg, section, *this);
	port_key = util::describeKey(cfg, section, "port");
	if (serial) link.loadFromConfigFile(cfg, section);
}

void DeviceChoice::dump(std::ostream& out) const
{
	out << "[" << section << "]\n";
	deviceBinder().dump(out, *this);
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
	cameraBinder().load(cfg, s, *this);
	if (driver == Driver::CameraSensor) sensor_sections = sectionsText(cfg, s);
	if (driver != Driver::Socket) return;
	socketBinder().load(cfg, s, *this);
	try
	{
		hw_serial::parseCameraAddress(address, s);
	}
	catch (const std::invalid_argument& e)
	{
		throw util::ConfigError(util::describeKey(cfg, s, "address") + ": " + e.what());
	}
}

void CameraChoice::dump(std::ostream& out) const
{
	out << "[device.camera]\n";
	cameraBinder().dump(out, *this);
	if (driver == Driver::Socket) socketBinder().dump(out, *this);
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
