#include <mrolr/hw_serial/SocketIo.h>

#include <mrpt/comms/CClientTCPSocket.h>

#include <arpa/inet.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <stdexcept>

namespace mrolr::hw_serial
{
namespace
{
/** CClientTCPSocket keeps its descriptor as a protected member and has no getter; a member
 * pointer formed through a derived class reads it from any instance (also those that
 * CServerTCPSocket::accept creates, which cannot be of a derived class). */
struct SocketHandle : mrpt::comms::CClientTCPSocket
{
	static int of(const mrpt::comms::CClientTCPSocket& s) { return s.*(&SocketHandle::m_hSock); }
};

bool stopped(const std::atomic<bool>* stop)
{
	return stop && stop->load();
}

/** Milliseconds to wait in the next slice; 0 when the deadline has passed. */
int sliceMs(SocketDeadline deadline)
{
	if (deadline == kNoSocketDeadline) return kSocketSliceMs;
	// rounded up: a deadline 0.4 ms away is not yet passed
	const auto left =
	    std::chrono::ceil<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
	return int(std::clamp<long long>(left.count(), 0, kSocketSliceMs));
}

/** Waits one slice for room to write; false when the socket failed or hung up. */
bool waitWritable(int fd, int ms, bool& ready)
{
	pollfd p{fd, POLLOUT, 0};
	const int r = ::poll(&p, 1, ms);
	if (r < 0) return errno == EINTR;
	ready = r > 0;
	return !(p.revents & (POLLERR | POLLHUP | POLLNVAL));
}
}  // namespace

uint16_t freeLoopbackPort()
{
	const int fd = ::socket(AF_INET, SOCK_STREAM, 0);
	if (fd < 0) throw std::runtime_error(std::string("socket(): ") + std::strerror(errno));
	sockaddr_in a{};
	a.sin_family = AF_INET;
	a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
	socklen_t len = sizeof(a);
	const bool ok = ::bind(fd, reinterpret_cast<sockaddr*>(&a), sizeof(a)) == 0 &&
	                ::getsockname(fd, reinterpret_cast<sockaddr*>(&a), &len) == 0;
	const int err = errno;
	::close(fd);
	if (!ok) throw std::runtime_error(std::string("no free port: ") + std::strerror(err));
	return ntohs(a.sin_port);
}

SocketDeadline deadlineIn(int ms)
{
	return std::chrono::steady_clock::now() + std::chrono::milliseconds(ms);
}

SocketIoStatus readExact(mrpt::comms::CClientTCPSocket& socket, size_t n, std::string& out,
                         SocketDeadline deadline, const std::atomic<bool>* stop)
{
	const size_t start = out.size();
	out.resize(start + n);
	size_t got = 0;
	auto result = SocketIoStatus::Done;
	while (got < n)
	{
		if (stopped(stop))
			result = SocketIoStatus::Stopped;
		else if (!socket.isConnected())
			result = SocketIoStatus::Closed;
		else if (const int ms = sliceMs(deadline); ms == 0)
			result = SocketIoStatus::TimedOut;
		else
		{
			try
			{
				// a between-chunks timeout of 0: take what has arrived, then come back here
				got += socket.readAsync(out.data() + start + got, n - got, ms, 0);
				continue;
			}
			catch (const std::exception&)
			{
				socket.close();
				result = SocketIoStatus::Closed;
			}
		}
		break;
	}
	out.resize(start + got);
	return result;
}

SocketIoStatus writeAll(mrpt::comms::CClientTCPSocket& socket, const std::string& bytes,
                        SocketDeadline deadline, const std::atomic<bool>* stop)
{
	size_t done = 0;
	while (done < bytes.size())
	{
		if (stopped(stop)) return SocketIoStatus::Stopped;
		const int fd = SocketHandle::of(socket);
		if (fd < 0) return SocketIoStatus::Closed;
		const int ms = sliceMs(deadline);
		if (ms == 0) return SocketIoStatus::TimedOut;
		bool ready = false;
		if (!waitWritable(fd, ms, ready)) return SocketIoStatus::Closed;
		if (!ready) continue;
		const ssize_t sent =
		    ::send(fd, bytes.data() + done, bytes.size() - done, MSG_NOSIGNAL | MSG_DONTWAIT);
		if (sent < 0 && (errno == EINTR || errno == EAGAIN || errno == EWOULDBLOCK)) continue;
		if (sent < 0) return SocketIoStatus::Closed;
		done += size_t(sent);
	}
	return SocketIoStatus::Done;
}

}  // namespace mrolr::hw_serial
