#pragma once
/** The error a serial driver throws when its device cannot be talked to. */

#include <mrolr/hw/Devices.h>

#include <stdexcept>
#include <string>

namespace mrolr::hw_serial
{
/** Thrown by a transport when the other end has gone (port closed, pty hung up, cable pulled). */
class TransportClosed : public std::runtime_error
{
 public:
	using std::runtime_error::runtime_error;
};

/** A serial device failed: what() reads "<device> on <port>: <what happened>", e.g.
 * "device.base on /dev/pts/3: timeout: no reply after 4 attempts of 200 ms (command STEP)". */
class SerialDeviceError : public hw::DeviceFailure
{
 public:
	enum class Kind
	{
		Timeout,       ///< no reply within the timeout, after every retry
		Garbage,       ///< only damaged or unreadable replies, after every retry
		Disconnected,  ///< the port closed or hung up
		Refused        ///< the device answered ERR with a code that retrying cannot fix
	};

	SerialDeviceError(Kind kind, const std::string& device, const std::string& port,
	                  const std::string& what_happened);

	Kind kind() const { return kind_; }
	const std::string& device() const { return device_; }
	const std::string& port() const { return port_; }

 private:
	Kind kind_;
	std::string device_, port_;
};

/** "timeout", "garbage", "disconnected", "refused". */
const char* kindName(SerialDeviceError::Kind kind);

/** The innermost "Message:" line of an MRPT exception's what(), without call stacks (the first
 * line of any other text), for error messages a user reads. */
std::string mrptMessage(const std::string& what);

}  // namespace mrolr::hw_serial
