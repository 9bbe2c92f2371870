// The robot's device factory: the simulator's devices or serial drivers per [device.*] section.
#include <mrolr/hw_serial/CameraSensorStereo.h>
#include <mrolr/hw_serial/CameraSocketClient.h>
#include <mrolr/hw_serial/SerialError.h>
#include <mrolr/mission/MissionDevices.h>
#include <mrolr/util/Config.h>

#include <mrpt/config/CConfigFileMemory.h>

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
	catch (const hw_serial::SerialDeviceError& e)
	{
		throw util::ConfigError(d.port_key + ": cannot use '" + d.link.port + "': " + e.what());
	}
}

template <typename Device>
Device* simOrFail(Device* sim, const DeviceChoice& d)
{
	if (!sim)
		throw util::ConfigError("[" + d.section +
		                        "] driver = sim: there is no simulator (give the world with "
		                        "--world or [simulator] world_file, or use driver = serial)");
	return sim;
}
}  // namespace

std::unique_ptr<hw_serial::SerialClient> MissionDevices::open(const DeviceChoice& d)
{
	auto client = hw_serial::openSerialClient(d.link);
	links_.push_back({d.section, d.link.port, client.get()});
	return client;
}

hw_serial::ImageSource MissionDevices::camera(const DeviceOptions& o, const SimDevices& sim)
{
	using Driver = CameraChoice::Driver;
	if (o.camera.driver == Driver::Sim)
	{
		if (!sim.head)
			throw util::ConfigError(o.camera.key +
			                        " = sim: there is no simulator to render the stereo pairs");
		return [head = sim.head] { return head->grab(); };
	}
	if (o.camera.driver == Driver::Socket)
	{
		std::shared_ptr<hw_serial::CameraSocketClient> client;
		try
		{
			client = std::make_shared<hw_serial::CameraSocketClient>(o.camera.address, o.camera.timeout_ms);
		}
		catch (const std::exception& e)
		{
			throw util::ConfigError(o.camera.key + " = socket: cannot use '" + o.camera.address +
			                        "': " + e.what());
		}
		camera_ = client;
		return [client] { return client->grab(); };
	}
	std::shared_ptr<hw_serial::CameraSensorStereo> cameras;
	try
	{
		cameras = std::make_shared<hw_serial::CameraSensorStereo>(
		    mrpt::config::CConfigFileMemory(o.camera.sensor_sections), "device.camera");
	}
	catch (const hw_serial::SerialDeviceError& e)
	{
		throw util::ConfigError(o.camera.key + " = camera_sensor: " + e.what());
	}
	camera_ = cameras;
	return [cameras] { return cameras->grab(); };
}

MissionDevices::MissionDevices(const DeviceOptions& o, const SimDevices& sim)
{
	if (o.base.serial)
		own_base_ = connect(o.base,
		                    [&] { return std::make_unique<hw_serial::SerialBase>(open(o.base)); });
	if (o.head.serial)
	{
		auto images = camera(o, sim);
		own_head_ = connect(
		    o.head, [&] { return std::make_unique<hw_serial::SerialHead>(open(o.head), images); });
	}
	if (o.arm.serial)
		own_arm_ =
		    connect(o.arm, [&] { return std::make_unique<hw_serial::SerialArm>(open(o.arm)); });
	base_ = own_base_ ? own_base_.get() : simOrFail(sim.base, o.base);
	head_ = own_head_ ? own_head_.get() : simOrFail(sim.head, o.head);
	arm_ = own_arm_ ? own_arm_.get() : simOrFail(sim.arm, o.arm);
}

MissionDevices::~MissionDevices() = default;

RobotDevices MissionDevices::devices()
{
	return {base_, head_, arm_, [this] { return links(); }};
}

std::vector<LinkReport> MissionDevices::links() const
{
	std::vector<LinkReport> out;
	for (const auto& l : links_) out.push_back({l.section, l.port, l.client->resends()});
	return out;
}

}  // namespace mrolr::mission
