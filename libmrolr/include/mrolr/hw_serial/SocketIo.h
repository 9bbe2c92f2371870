#pragma once
/** Bounded reads and writes on an mrpt::comms::CClientTCPSocket, for the camera socket.
 *
 * Reads use CClientTCPSocket::readAsync in short slices (so a stop flag is seen promptly); a
 * socket that readAsync closed was hung up by its peer. Writes do not use writeAsync: in MRPT
 * 2.5.8 it sends without MSG_NOSIGNAL (a peer that has gone raises SIGPIPE, which ends the
 * process) and retries a failing send() for ever once epoll reports the error; so they go
 * through send(MSG_NOSIGNAL) and poll() on the socket's descriptor. */

#include <atomic>
#include <chrono>
#include <cstdint>
#include <string>

namespace mrpt::comms
{
class CClientTCPSocket;
}

namespace mrolr::hw_serial
{
enum class SocketIoStatus
{
	Done,      ///< all bytes read or written
	TimedOut,  ///< the deadline passed first
	Closed,    ///< the peer hung up (or the socket failed)
	Stopped    ///< the stop flag was raised
};

using SocketDeadline = std::chrono::steady_clock::time_point;

/** No deadline: wait until done, closed or stopped. */
constexpr SocketDeadline kNoSocketDeadline = SocketDeadline::max();

/** Polls are cut into slices of this length, so that a raised stop flag ends a wait promptly. */
constexpr int kSocketSliceMs = 20;

/** Reads exactly @p n bytes into @p out (appended) by @p deadline. @p stop may be null. */
SocketIoStatus readExact(mrpt::comms::CClientTCPSocket& socket, size_t n, std::string& out,
                         SocketDeadline deadline, const std::atomic<bool>* stop = nullptr);

/** Writes all of @p bytes by @p deadline. @p stop may be null. */
SocketIoStatus writeAll(mrpt::comms::CClientTCPSocket& socket, const std::string& bytes,
                        SocketDeadline deadline, const std::atomic<bool>* stop = nullptr);

/** A TCP port free on 127.0.0.1 now (the system picks it for a probe socket that is closed
 * again, never connected, so the port is free at once; another process may still take it
 * before it is used). CServerTCPSocket cannot report the port it got for 0, hence this. Throws
 * std::runtime_error when the system has none. */
uint16_t freeLoopbackPort();

/** The deadline @p ms milliseconds from now. */
SocketDeadline deadlineIn(int ms);

}  // namespace mrolr::hw_serial
