#pragma once
/** The robot side of the camera socket: the head's stereo pairs from a CameraServer on
 * 127.0.0.1 (frames as in CameraWire.h, docs/serial.md "The camera socket"). Wrapped in an
 * ImageSource it feeds SerialHead, which stamps the pairs with the head's angles:
 *
 *     auto camera = std::make_shared<hw_serial::CameraSocketClient>("127.0.0.1:5801", 2000);
 *     hw_serial::SerialHead head(std::move(client), [camera] { return camera->grab(); });
 */

#include <mrolr/hw/Devices.h>
#include <mrolr/hw_serial/CameraWire.h>
#include <mrolr/hw_serial/SerialError.h>
#include <mrolr/hw_serial/SocketIo.h>

#include <cstdint>
#include <memory>
#include <string>

namespace mrpt::comms
{
class CClientTCPSocket;
}

namespace mrolr::hw_serial
{
/** The port of "127.0.0.1:PORT" (PORT decimal 1..65535, no sign, no leading zero, nothing
 * around). Only the loopback address is accepted: the camera socket carries no authentication.
 * Throws std::invalid_argument naming @p device and the address otherwise. */
uint16_t parseCameraAddress(const std::string& address, const std::string& device);

/** One request at a time; not thread-safe. Every failure is a SerialDeviceError naming the
 * device section and the address: Disconnected (cannot connect, or the server hung up),
 * Timeout (no whole reply within the timeout), Garbage (bytes that are not a reply to this
 * request, or do not deserialize), Refused (the server answered that its grab failed). After a
 * failure the connection is closed and the next grab() connects again, so a server that comes
 * back is used again and a late reply is never taken for the next one. */
class CameraSocketClient
{
 public:
	/** Connects to @p address ("127.0.0.1:PORT", see parseCameraAddress) within @p timeout_ms
	 * (1..600000). Throws std::invalid_argument on a malformed address or timeout, and
	 * SerialDeviceError Disconnected when nothing listens there. */
	CameraSocketClient(const std::string& address, int timeout_ms,
	                   const std::string& device = "device.camera");
	~CameraSocketClient();
	CameraSocketClient(const CameraSocketClient&) = delete;
	CameraSocketClient& operator=(const CameraSocketClient&) = delete;

	/** Requests one pair and waits at most the timeout for all of it: both images 8-bit grey as
	 * the server's grab gave them, its head angles and time_s. */
	hw::StereoImages grab();

	const std::string& address() const { return address_; }
	const std::string& device() const { return device_; }
	int timeoutMs() const { return timeout_ms_; }

 private:
	void connect();
	/** Closes the connection and throws. */
	[[noreturn]] void fail(SerialDeviceError::Kind kind, const std::string& what_happened);
	void sendRequest(uint32_t seq, SocketDeadline deadline);
	CameraFrameHeader receiveHeader(uint32_t seq, SocketDeadline deadline);
	std::string receive(size_t n, SocketDeadline deadline, const char* what);

	std::string address_, device_;
	uint16_t port_;
	int timeout_ms_;
	uint32_t seq_;
	std::unique_ptr<mrpt::comms::CClientTCPSocket> socket_;
};

}  // namespace mrolr::hw_serial
