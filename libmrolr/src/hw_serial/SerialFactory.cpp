#include <mrolr/hw_serial/SerialFactory.h>
#include <mrolr/hw_serial/SerialPortTransport.h>
#include <mrolr/util/OptionsBinder.h>

#include <ostream>

namespace mrolr::hw_serial
{
namespace
{
using L = SerialLinkConfig;
constexpr auto kOpt = util::Presence::Optional;  // the link's timing: measured defaults

const util::OptionsBinder<L>& linkBinder()
{
	static const auto b =
	    util::OptionsBinder<L>()
	        .text("port", &L::port)
	        .integer("baud", &L::baud, 50, 4000000)
	        .integer("timeout_ms", [](L& o) -> int& { return o.link.timeout_ms; }, 1, 60000, kOpt)
	        .integer("motion_timeout_ms", [](L& o) -> int& { return o.link.motion_timeout_ms; }, 1,
	                 600000, kOpt)
	        .integer("retries", [](L& o) -> int& { return o.link.retries; }, 0, 100, kOpt);
	return b;
}
}  // namespace

void SerialLinkConfig::loadFromConfigFile(const mrpt::config::CConfigFileBase& cfg,
                                          const std::string& section)
{
	linkBinder().load(cfg, section, *this);
	if (port.empty()) throw util::ConfigError(util::describeKey(cfg, section, "port") + ": empty");
	link.device = section;
}

void SerialLinkConfig::dump(std::ostream& out) const
{
	linkBinder().dump(out, *this);
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
