// The mission's device factory: sim devices or serial drivers per [device.*] section.
#include <mrolr/hw_serial/SerialError.h>
#include <mrolr/mission/MissionDevices.h>
#include <mrolr/util/Config.h>

namespace mrolr::mission
{
namespace
{
/** Builds a serial driver, turning a failure to connect into an error about the port key. */
template <typename Make>
auto connect(const DeviceChoice& d, Make make)
{
	try
	{
		return make();
	}
	catch (const hw::SerialDeviceError& e)
	{
		throw util::ConfigError(d.port_key + ": cannot use '" + d.link.port + "': " + e.what());
	}
}
}  // namespace

std::unique_ptr<hw::SerialClient> MissionDevices::open(const DeviceChoice& d)
{
	auto client = hw::openSerialClient(d.link);
	links_.push_back({d.section, d.link.port, client.get()});
	return client;
}

MissionDevices::MissionDevices(const DeviceOptions& o, SimulatedLab& lab)
{
	base_ = &lab.base(), head_ = &lab.head(), arm_ = &lab.arm();
	if (o.base.serial)
		base_ = (own_base_ = connect(o.base, [&]
		                             { return std::make_unique<hw::SerialBase>(open(o.base)); }))
		            .get();
	auto images = [&lab] { return lab.head().grab(); };
	if (o.head.serial)
		head_ = (own_head_ = connect(o.head, [&]
		                             { return std::make_unique<hw::SerialHead>(open(o.head), images); }))
		            .get();
	if (o.arm.serial)
		arm_ = (own_arm_ = connect(o.arm, [&]
		                           { return std::make_unique<hw::SerialArm>(open(o.arm)); }))
		           .get();
}

MissionDevices::~MissionDevices() = default;

std::vector<LinkReport> MissionDevices::links() const
{
	std::vector<LinkReport> out;
	for (const auto& l : links_) out.push_back({l.section, l.port, l.client->resends()});
	return out;
}

}  // namespace mrolr::mission
