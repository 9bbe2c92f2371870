#include <mrolr/hw_serial/CameraServer.h>
#include <mrolr/hw_serial/CameraWire.h>
#include <mrolr/hw_serial/SerialError.h>
#include <mrolr/hw_serial/SocketIo.h>

#include <mrpt/comms/CClientTCPSocket.h>
#include <mrpt/comms/CServerTCPSocket.h>

#include <chrono>
#include <stdexcept>
#include <thread>

namespace mrolr::hw_serial
{
namespace
{
constexpr const char* kLoopback = "127.0.0.1";
/** Connections waiting while one is served. */
constexpr int kBacklog = 4;
/** A request started must be complete within this (a client that hangs mid-frame is dropped). */
constexpr int kFrameRestMs = 1000;
/** A client that stops reading a reply for this long is dropped. */
constexpr int kReplyWriteMs = 5000;
/** Attempts at a free port: another process may take the probed port before we bind it. */
constexpr int kFreePortAttempts = 5;

std::unique_ptr<mrpt::comms::CServerTCPSocket> listenOn(uint16_t port)
{
	try
	{
		// LVL_ERROR: accept() with a timeout logs a warning on every timeout otherwise
		return std::make_unique<mrpt::comms::CServerTCPSocket>(port, kLoopback, kBacklog,
		                                                       mrpt::system::LVL_ERROR);
	}
	catch (const std::exception& e)
	{
		throw std::runtime_error("camera server: cannot listen on " + std::string(kLoopback) + ":" +
		                         std::to_string(port) + ": " + mrptMessage(e.what()));
	}
}
}  // namespace

CameraServer::CameraServer(ImageSource grab, uint16_t port) : grab_(std::move(grab))
{
	if (!grab_) throw std::invalid_argument("camera server: no grab function");
	for (int attempt = 1; !listener_; ++attempt)
	{
		port_ = port != 0 ? port : freeLoopbackPort();
		try
		{
			listener_ = listenOn(port_);
		}
		catch (const std::runtime_error&)
		{
			if (port != 0 || attempt == kFreePortAttempts) throw;
		}
	}
	thread_ = std::thread([this] { loop(); });
}

CameraServer::~CameraServer()
{
	stop();
}

std::string CameraServer::address() const
{
	return std::string(kLoopback) + ":" + std::to_string(port_);
}

void CameraServer::stop()
{
	stop_ = true;
	if (thread_.joinable()) thread_.join();
	listener_.reset();
}

void CameraServer::loop()
{
	while (!stop_)
	{
		// nothing may escape the thread (std::terminate): a failure drops the connection only
		try
		{
			auto client = listener_->accept(kSocketSliceMs);
			if (!client) continue;
			++accepted_;
			serve(*client);
		}
		catch (const std::exception&)
		{
			// a failure that repeats at once must not spin the thread
			std::this_thread::sleep_for(std::chrono::milliseconds(kSocketSliceMs));
		}
	}
}

void CameraServer::serve(mrpt::comms::CClientTCPSocket& client)
{
	client.setTCPNoDelay(1);
	while (!stop_ && answerOne(client))
	{
	}
	client.close();
}

bool CameraServer::answerOne(mrpt::comms::CClientTCPSocket& client)
{
	std::string header;
	// an idle client may wait for ever before its next request; once it starts one, the rest
	// must follow promptly
	if (readExact(client, 1, header, kNoSocketDeadline, &stop_) != SocketIoStatus::Done)
		return false;
	if (readExact(client, kCameraHeaderBytes - 1, header, deadlineIn(kFrameRestMs), &stop_) !=
	    SocketIoStatus::Done)
		return false;
	CameraFrameHeader request;
	try
	{
		request = decodeCameraHeader(header);
	}
	catch (const CameraWireError&)
	{
		++rejected_;
		return false;
	}
	if (request.kind != CameraFrameKind::Request)
	{
		++rejected_;
		return false;
	}
	const std::string frame = reply(request.seq);
	return writeAll(client, frame, deadlineIn(kReplyWriteMs), &stop_) == SocketIoStatus::Done;
}

std::string CameraServer::reply(uint32_t seq)
{
	try
	{
		std::string frame = encodeCameraImages(seq, grab_());
		++served_;
		return frame;
	}
	catch (const std::exception& e)
	{
		return encodeCameraError(seq, mrptMessage(e.what()));
	}
	catch (...)
	{
		return encodeCameraError(seq, "the grab function threw an unknown exception");
	}
}

}  // namespace mrolr::hw_serial
