#include <mrolr/hw_serial/CameraSocketClient.h>
#include <mrolr/hw_serial/Framing.h>

#include <mrpt/comms/CClientTCPSocket.h>

#include <algorithm>
#include <random>
#include <stdexcept>

namespace mrolr::hw_serial
{
namespace
{
constexpr const char* kLoopbackHost = "127.0.0.1";
constexpr int kMaxTimeoutMs = 600000;
using Kind = SerialDeviceError::Kind;

bool allDigits(const std::string& s)
{
	return std::all_of(s.begin(), s.end(), [](char c) { return c >= '0' && c <= '9'; });
}

std::invalid_argument badAddress(const std::string& address, const std::string& device,
                                 const std::string& why)
{
	return std::invalid_argument(device + ": camera address '" + printableBytes(address) + "' " +
	                             why + " (expected 127.0.0.1:PORT with PORT 1..65535)");
}

/** A random first number, so a client that reconnects is not answered for its predecessor. */
uint32_t firstSeq()
{
	std::random_device rd;
	return std::uniform_int_distribution<uint32_t>(1, 1u << 30)(rd);
}
}  // namespace

uint16_t parseCameraAddress(const std::string& address, const std::string& device)
{
	const std::string host = std::string(kLoopbackHost) + ":";
	if (address.find(':') == std::string::npos) throw badAddress(address, device, "has no port");
	if (address.compare(0, host.size(), host) != 0)
		throw badAddress(address, device,
		                 "is not on 127.0.0.1, the only host the camera socket may use");
	const std::string port = address.substr(host.size());
	if (port.empty() || port.size() > 5 || port[0] == '0' || !allDigits(port))
		throw badAddress(address, device, "has a malformed port");
	const unsigned long value = std::stoul(port);
	if (value > 65535) throw badAddress(address, device, "has a port beyond 65535");
	return uint16_t(value);
}

CameraSocketClient::CameraSocketClient(const std::string& address, int timeout_ms,
                                       const std::string& device)
    : address_(address),
      device_(device),
      port_(parseCameraAddress(address, device)),
      timeout_ms_(timeout_ms),
      seq_(firstSeq())
{
	if (timeout_ms < 1 || timeout_ms > kMaxTimeoutMs)
		throw std::invalid_argument(device + ": camera timeout " + std::to_string(timeout_ms) +
		                            " ms is outside 1..600000");
	connect();
}

CameraSocketClient::~CameraSocketClient() = default;

void CameraSocketClient::connect()
{
	socket_ = std::make_unique<mrpt::comms::CClientTCPSocket>();
	try
	{
		socket_->connect(kLoopbackHost, port_, unsigned(timeout_ms_));
	}
	catch (const std::exception& e)
	{
		fail(Kind::Disconnected, "cannot connect to the camera server: " + mrptMessage(e.what()));
	}
	// a request is 12 bytes: without this, Nagle's algorithm may hold it back
	socket_->setTCPNoDelay(1);
}

void CameraSocketClient::fail(SerialDeviceError::Kind kind, const std::string& what_happened)
{
	socket_.reset();
	throw SerialDeviceError(kind, device_, address_, what_happened);
}

hw::StereoImages CameraSocketClient::grab()
{
	if (!socket_ || !socket_->isConnected()) connect();
	const uint32_t seq = seq_++;
	const SocketDeadline deadline = deadlineIn(timeout_ms_);
	sendRequest(seq, deadline);
	const CameraFrameHeader header = receiveHeader(seq, deadline);
	const std::string payload = receive(header.length, deadline, "the reply's payload");
	if (header.kind == CameraFrameKind::Error)
		fail(Kind::Refused, "the camera server could not grab: " + printableBytes(payload, 400));
	try
	{
		return decodeCameraImages(payload);
	}
	catch (const CameraWireError& e)
	{
		fail(Kind::Garbage, e.what());
	}
}

void CameraSocketClient::sendRequest(uint32_t seq, SocketDeadline deadline)
{
	switch (writeAll(*socket_, encodeCameraRequest(seq), deadline))
	{
		case SocketIoStatus::Done:
			return;
		case SocketIoStatus::TimedOut:
			fail(Kind::Timeout,
			     "the request could not be sent within " + std::to_string(timeout_ms_) + " ms");
		default:
			fail(Kind::Disconnected, "the camera server closed the connection");
	}
}

CameraFrameHeader CameraSocketClient::receiveHeader(uint32_t seq, SocketDeadline deadline)
{
	const std::string bytes = receive(kCameraHeaderBytes, deadline, "the reply's header");
	CameraFrameHeader header;
	try
	{
		header = decodeCameraHeader(bytes);
	}
	catch (const CameraWireError& e)
	{
		fail(Kind::Garbage, e.what());
	}
	if (header.kind == CameraFrameKind::Request)
		fail(Kind::Garbage, "the server sent a request frame instead of a reply");
	if (header.seq != seq)
		fail(Kind::Garbage, "reply to request " + std::to_string(header.seq) + ", expected " +
		                        std::to_string(seq));
	return header;
}

std::string CameraSocketClient::receive(size_t n, SocketDeadline deadline, const char* what)
{
	std::string bytes;
	switch (readExact(*socket_, n, bytes, deadline))
	{
		case SocketIoStatus::Done:
			return bytes;
		case SocketIoStatus::TimedOut:
			fail(Kind::Timeout, "no whole reply within " + std::to_string(timeout_ms_) + " ms (" +
			                        std::to_string(bytes.size()) + " of " + std::to_string(n) +
			                        " bytes of " + what + ")");
		default:
			fail(Kind::Disconnected, "the camera server closed the connection (" +
			                             std::to_string(bytes.size()) + " of " + std::to_string(n) +
			                             " bytes of " + what + ")");
	}
}

}  // namespace mrolr::hw_serial
