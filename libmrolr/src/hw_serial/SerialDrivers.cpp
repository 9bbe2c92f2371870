#include <mrolr/geometry/GeometryError.h>
#include <mrolr/hw_serial/DeviceProtocols.h>
#include <mrolr/hw_serial/Message.h>
#include <mrolr/hw_serial/SerialDrivers.h>

#include <algorithm>
#include <cmath>

namespace mrolr::hw_serial
{
namespace
{
void requireIdentity(SerialClient& client, const char* id)
{
	const auto fields = client.call("ID?", {});
	if (fields.empty() || fields[0] != id)
		throw SerialDeviceError(SerialDeviceError::Kind::Refused, client.options().device,
		                        client.portName(),
		                        std::string("expected a ") + id + " but the device answered ID '" +
		                            (fields.empty() ? "" : fields[0]) + "'");
}

/** Numbers of a reply, a malformed reply reported as garbage naming device and port. */
std::vector<double> replyNumbers(const SerialClient& client, const std::vector<std::string>& f,
                                 size_t count, const std::string& what)
{
	try
	{
		return parseNumbers(f, count, what);
	}
	catch (const std::invalid_argument& e)
	{
		throw SerialDeviceError(SerialDeviceError::Kind::Garbage, client.options().device,
		                        client.portName(), std::string("malformed reply: ") + e.what());
	}
}

/** Runs @p fn; a LIMIT refusal is rethrown as the interface's exception type @p E. */
template <typename E, typename Fn>
auto mapLimit(SerialClient& client, Fn fn)
{
	try
	{
		return fn();
	}
	catch (const SerialDeviceError& e)
	{
		if (e.kind() == SerialDeviceError::Kind::Refused &&
		    client.lastErrorCode() == errcode::kLimit)
			throw E(e.what());
		throw;
	}
}
}  // namespace

SerialBase::SerialBase(std::unique_ptr<SerialClient> client) : client_(std::move(client))
{
	requireIdentity(*client_, kBaseId);
}

void SerialBase::step(const base::WheelControl& u)
{
	// the device answers when the step is done: wait for dt on top of the usual timeout
	const int wait_ms = client_->options().timeout_ms + int(std::ceil(u.dt_s * 1000));
	client_->call("STEP", numberFields({u.v1_mps, u.v2_mps, u.dt_s}), wait_ms);
}

hw::Odometry SerialBase::odometry() const
{
	const auto f = client_->call("ODO?", {});
	hw::Odometry o;
	if (f.size() != 7)
		replyNumbers(*client_, f, 7, "ODO? reply");  // throws, naming the field count
	const auto pose = replyNumbers(*client_, {f[0], f[1], f[2]}, 3, "ODO? pose");
	o.xv_zxphi = Eigen::Vector3d(pose[0], pose[1], pose[2]);
	try
	{
		o.ticks_right = parseInteger(f[3], "ODO? ticks_r");
		o.ticks_left = parseInteger(f[4], "ODO? ticks_l");
	}
	catch (const std::invalid_argument& e)
	{
		replyNumbers(*client_, {"x"}, 1, e.what());  // reported as a malformed reply
	}
	o.time_s = replyNumbers(*client_, {f[5]}, 1, "ODO? t_s")[0];
	if (f[6] != "0" && f[6] != "1") replyNumbers(*client_, {"x"}, 1, "ODO? bumper is not 0 or 1");
	o.bumper = f[6] == "1";
	return o;
}

SerialHead::SerialHead(std::unique_ptr<SerialClient> client, ImageSource images)
    : client_(std::move(client)), images_(std::move(images))
{
	requireIdentity(*client_, kHeadId);
}

double SerialHead::moveTo(const geometry::HeadAngles& t)
{
	const auto f = mapLimit<geometry::FixationError>(
	    *client_,
	    [&]
	    {
		    return client_->call("MOVE", numberFields({t.pan, t.tilt, t.verg_left, t.verg_right}),
		                         client_->options().motion_timeout_ms);
	    });
	return replyNumbers(*client_, f, 1, "MOVE reply")[0];
}

geometry::HeadAngles SerialHead::angles() const
{
	const auto v = replyNumbers(*client_, client_->call("ANG?", {}), 4, "ANG? reply");
	return geometry::HeadAngles{v[0], v[1], v[2], v[3]};
}

hw::StereoImages SerialHead::grab()
{
	if (!images_)
		throw std::logic_error(client_->options().device +
		                       ": the serial head has no image source (the cameras are not on the "
		                       "serial line)");
	hw::StereoImages pair = images_();
	pair.angles = angles();
	return pair;
}

SerialArm::SerialArm(std::unique_ptr<SerialClient> client) : client_(std::move(client))
{
	requireIdentity(*client_, kArmId);
}

void SerialArm::moveTo(const hw::ArmJoints& j)
{
	try
	{
		mapLimit<std::out_of_range>(
		    *client_,
		    [&]
		    {
			    return client_->call("MOVE", numberFields(std::vector<double>(j.begin(), j.end())),
			                         client_->options().motion_timeout_ms);
		    });
	}
	catch (const SerialDeviceError& e)
	{  // the arm stalled on the way: the same exception as in process, the line still alive
		if (e.kind() == SerialDeviceError::Kind::Refused &&
		    client_->lastErrorCode() == errcode::kBlocked)
			throw hw::ArmBlocked(e.what());
		throw;
	}
}

hw::ArmJoints SerialArm::joints() const
{
	const auto v = replyNumbers(*client_, client_->call("JNT?", {}), 7, "JNT? reply");
	hw::ArmJoints j;
	std::copy(v.begin(), v.end(), j.begin());
	return j;
}

void SerialArm::setGripper(bool closed)
{
	client_->call("GRIP", {closed ? "1" : "0"});
}

namespace
{
/** `GRIP?` → (closed, width_mm). */
std::pair<bool, double> gripperState(SerialClient& client)
{
	const auto f = client.call("GRIP?", {});
	if (f.size() != 2 || (f[0] != "0" && f[0] != "1"))
		replyNumbers(client, {"x"}, 1, "GRIP? reply is not '0|1 width_mm'");
	return {f[0] == "1", replyNumbers(client, {f[1]}, 1, "GRIP? width_mm")[0]};
}
}  // namespace

bool SerialArm::gripperClosed() const
{
	return gripperState(*client_).first;
}

double SerialArm::gripperWidthMm() const
{
	return gripperState(*client_).second;
}

void SerialArm::dock(bool docked)
{
	client_->call("DOCK", {docked ? "1" : "0"});
}

bool SerialArm::docked() const
{
	const auto reply = client_->call("DOCK?", {});
	if (reply.size() != 1 || (reply[0] != "0" && reply[0] != "1"))
		throw SerialDeviceError(SerialDeviceError::Kind::Garbage, client_->options().device,
		                        client_->portName(), "malformed reply: DOCK? is not '0|1'");
	return reply[0] == "1";
}

}  // namespace mrolr::hw_serial
