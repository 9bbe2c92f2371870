// The mission's device sections (docs/mission.md "Configuration", docs/serial.md "Config keys").
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

void DeviceOptions::loadFromConfigFile(const mrpt::config::CConfigFileBase& cfg)
{
	base.loadFromConfigFile(cfg, "device.base");
	head.loadFromConfigFile(cfg, "device.head");
	arm.loadFromConfigFile(cfg, "device.arm");
}

void DeviceOptions::dump(std::ostream& out) const
{
	for (const auto* d : {&base, &head, &arm})
	{
		d->dump(out);
		out << "\n";
	}
}

}  // namespace mrolr::mission
