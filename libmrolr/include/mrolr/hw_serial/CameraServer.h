#pragma once
/** The world side of the camera socket: serves the head's stereo pairs on 127.0.0.1 to one
 * client at a time, so that a robot in another process (CameraSocketClient) sees the simulated
 * cameras as it would a frame grabber. Frames as in CameraWire.h (docs/serial.md "The camera
 * socket"). */

#include <mrolr/hw_serial/SerialDrivers.h>

#include <atomic>
#include <cstdint>
#include <memory>
#include <string>
#include <thread>

namespace mrpt::comms
{
class CClientTCPSocket;
class CServerTCPSocket;
}  // namespace mrpt::comms

namespace mrolr::hw_serial
{
class CameraServer
{
 public:
	/** Listens on 127.0.0.1:@p port (0: a free port the system picks; see port()) with
	 * mrpt::comms::CServerTCPSocket and serves from its own thread: each request calls @p grab
	 * once (from that thread) and answers its pair, or an error frame with the message when
	 * @p grab throws. A client that hangs up, sends a frame that is not a request, leaves a
	 * frame unfinished for a second or stops reading a reply for 5 s is dropped, and the next
	 * client is served. Throws std::runtime_error when it cannot listen (the port is taken; a
	 * port a previous server used may stay refused for about a minute, as MRPT's socket does not
	 * set SO_REUSEADDR, which port 0 avoids). */
	explicit CameraServer(ImageSource grab, uint16_t port = 0);
	/** stop() */
	~CameraServer();
	CameraServer(const CameraServer&) = delete;
	CameraServer& operator=(const CameraServer&) = delete;

	/** The port listened on. */
	uint16_t port() const { return port_; }
	/** "127.0.0.1:PORT", what CameraSocketClient is given. */
	std::string address() const;

	/** Ends the thread (within a poll slice of 20 ms, or when a running grab returns), closes the
	 * connection and stops listening: clients see a disconnect. Idempotent. */
	void stop();

	/** Requests answered with a pair so far (grabbed and encoded; the client may have gone). */
	size_t served() const { return served_; }
	/** Connections accepted so far. */
	size_t accepted() const { return accepted_; }
	/** Connections dropped for a frame that is not a request (garbage from the client). */
	size_t rejected() const { return rejected_; }

 private:
	void loop();
	void serve(mrpt::comms::CClientTCPSocket& client);
	bool answerOne(mrpt::comms::CClientTCPSocket& client);
	std::string reply(uint32_t seq);

	ImageSource grab_;
	std::unique_ptr<mrpt::comms::CServerTCPSocket> listener_;
	uint16_t port_ = 0;
	std::atomic<bool> stop_{false};
	std::atomic<size_t> served_{0}, accepted_{0}, rejected_{0};
	std::thread thread_;
};

}  // namespace mrolr::hw_serial
