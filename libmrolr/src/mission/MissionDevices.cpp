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

/** A serial device and the lab's device that shadows it (gets the same commands). */
template <typename Device>
struct Pair
{
	std::unique_ptr<Device> serial;
	Device& lab;
};

/** A serial base whose steps also go to the lab's base (its truth then follows). */
class ShadowedBase : public hw::BaseDevice
{
 public:
	explicit ShadowedBase(Pair<hw::BaseDevice> d) : d_(std::move(d)) {}
	void step(const base::WheelControl& u) override
	{
		d_.serial->step(u);
		d_.lab.step(u);
	}
	hw::Odometry odometry() const override { return d_.serial->odometry(); }

 private:
	Pair<hw::BaseDevice> d_;
};

class ShadowedHead : public hw::HeadDevice
{
 public:
	explicit ShadowedHead(Pair<hw::HeadDevice> d) : d_(std::move(d)) {}
	double moveTo(const geometry::HeadAngles& target) override
	{
		const double settle_s = d_.serial->moveTo(target);
		d_.lab.moveTo(target);
		return settle_s;
	}
	geometry::HeadAngles angles() const override { return d_.serial->angles(); }
	hw::StereoImages grab() override { return d_.serial->grab(); }

 private:
	Pair<hw::HeadDevice> d_;
};

class ShadowedArm : public hw::ArmDevice
{
 public:
	explicit ShadowedArm(Pair<hw::ArmDevice> d) : d_(std::move(d)) {}
	void moveTo(const hw::ArmJoints& joints) override
	{
		d_.serial->moveTo(joints);
		d_.lab.moveTo(joints);
	}
	hw::ArmJoints joints() const override { return d_.serial->joints(); }
	void setGripper(bool closed) override
	{
		d_.serial->setGripper(closed);
		d_.lab.setGripper(closed);
	}
	bool gripperClosed() const override { return d_.serial->gripperClosed(); }
	double gripperWidthMm() const override { return d_.serial->gripperWidthMm(); }

 private:
	Pair<hw::ArmDevice> d_;
};

/** The serial driver itself when the lab's device is behind its port, else a shadowed one. */
template <typename Shadowed, typename Device>
std::unique_ptr<Device> shadowUnlessBehind(const DeviceChoice& d, std::unique_ptr<Device> serial,
                                           Device& lab)
{
	if (d.lab_behind_port) return serial;
	return std::make_unique<Shadowed>(Pair<Device>{std::move(serial), lab});
}
}  // namespace

std::unique_ptr<hw::SerialClient> MissionDevices::open(const DeviceChoice& d)
{
	auto client = hw::openSerialClient(d.link);
	links_.push_back({d.section, d.link.port, client.get(), d.lab_behind_port});
	return client;
}

void MissionDevices::makeBase(const DeviceChoice& d, SimulatedLab& lab)
{
	std::unique_ptr<hw::BaseDevice> serial =
	    connect(d, [&] { return std::make_unique<hw::SerialBase>(open(d)); });
	own_base_ = shadowUnlessBehind<ShadowedBase, hw::BaseDevice>(d, std::move(serial), lab.base());
	base_ = own_base_.get();
}

void MissionDevices::makeHead(const DeviceChoice& d, SimulatedLab& lab)
{
	auto images = [&lab] { return lab.head().grab(); };
	std::unique_ptr<hw::HeadDevice> serial =
	    connect(d, [&] { return std::make_unique<hw::SerialHead>(open(d), images); });
	own_head_ = shadowUnlessBehind<ShadowedHead, hw::HeadDevice>(d, std::move(serial), lab.head());
	head_ = own_head_.get();
}

void MissionDevices::makeArm(const DeviceChoice& d, SimulatedLab& lab)
{
	std::unique_ptr<hw::ArmDevice> serial =
	    connect(d, [&] { return std::make_unique<hw::SerialArm>(open(d)); });
	own_arm_ = shadowUnlessBehind<ShadowedArm, hw::ArmDevice>(d, std::move(serial), lab.arm());
	arm_ = own_arm_.get();
}

MissionDevices::MissionDevices(const DeviceOptions& o, SimulatedLab& lab)
{
	base_ = &lab.base(), head_ = &lab.head(), arm_ = &lab.arm();
	if (o.base.serial) makeBase(o.base, lab);
	if (o.head.serial) makeHead(o.head, lab);
	if (o.arm.serial) makeArm(o.arm, lab);
}

MissionDevices::~MissionDevices() = default;

std::vector<LinkReport> MissionDevices::links() const
{
	std::vector<LinkReport> out;
	for (const auto& l : links_)
		out.push_back({l.section, l.port, l.client->resends(), l.lab_behind_port});
	return out;
}

}  // namespace mrolr::mission
