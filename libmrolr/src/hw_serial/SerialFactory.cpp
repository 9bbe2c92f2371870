#include <mrolr/hw_serial/SerialFactory.h>
#include <mrolr/hw_serial/SerialPortTransport.h>
#include <mrolr/util/Config.h>

#include <ostream>

namespace mrolr::hw_serial
{
void SerialLinkConfig::loadFromConfigFile(const mrpt::config::CConfigFileBase& cfg,
                                          const std::string& section)
{
	port = util::readString(cfg, section, "port");
	if (port.empty()) throw util::ConfigError(util::describeKey(cfg, section, "port") + ": empty");
	baud = int(util::readInt(cfg, section, "baud"));
	util::requireInRange(cfg, section, "baud", baud, 50, 4000000);
	link.device = section;
	link.timeout_ms = int(util::readInt(cfg, section, "timeout_ms", link.timeout_ms));
	util::requireInRange(cfg, section, "timeout_ms", link.timeout_ms, 1, 60000);
	link.motion_timeout_ms =
	    int(util::readInt(cfg, section, "motion_timeout_ms", link.motion_timeout_ms));
	util::requireInRange(cfg, section, "motion_timeout_ms", link.motion_timeout_ms, 1, 600000);
	link.retries = int(util::readInt(cfg, section, "retries", link.retries));
	util::requireInRange(cfg, section, "retries", link.retries, 0, 100);
}

void SerialLinkConfig::dump(std::ostream& out) const
{
	out << "port = " << port << "\nbaud = " << baud << "\ntimeout_ms = " << link.timeout_ms
	    << "\nmotion_timeout_ms = " << link.motion_timeout_ms << "\nretries = " << link.retries
	    << "\n";
}

std::unique_ptr<SerialClient> openSerialClient(const SerialLinkConfig& config)
{
	try
	{
		return std::make_unique<SerialClient>(
		    std::make_unique<SerialPortTransport>(config.port, config.baud), config.link);
	}
	catch (const TransportClosed& e)
	{
		throw SerialDeviceError(SerialDeviceError::Kind::Disconnected, config.link.device,
		                        config.port, e.what());
	}
}

namespace
{
SerialLinkConfig readLink(const mrpt::config::CConfigFileBase& cfg, const std::string& section)
{
	SerialLinkConfig c;
	c.loadFromConfigFile(cfg, section);
	return c;
}
}  // namespace

std::unique_ptr<hw::BaseDevice> makeSerialBaseDevice(const mrpt::config::CConfigFileBase& cfg,
                                                 const std::string& section)
{
	return std::make_unique<SerialBase>(openSerialClient(readLink(cfg, section)));
}

std::unique_ptr<hw::HeadDevice> makeSerialHeadDevice(const mrpt::config::CConfigFileBase& cfg,
                                                 const std::string& section, ImageSource images)
{
	return std::make_unique<SerialHead>(openSerialClient(readLink(cfg, section)),
	                                    std::move(images));
}

std::unique_ptr<hw::ArmDevice> makeSerialArmDevice(const mrpt::config::CConfigFileBase& cfg,
                                               const std::string& section)
{
	return std::make_unique<SerialArm>(openSerialClient(readLink(cfg, section)));
}

}  // namespace mrolr::hw_serial
