#include <mrolr/hw_serial/Transport.h>

#include <poll.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace mrolr::hw_serial
{
void FdTransport::write(const std::string& bytes)
{
	size_t done = 0;
	while (done < bytes.size())
	{
		const ssize_t n = ::write(fd_, bytes.data() + done, bytes.size() - done);
		if (n < 0 && errno == EINTR) continue;
		if (n < 0) throw TransportClosed(name_ + ": write failed: " + std::strerror(errno));
		done += size_t(n);
	}
}

std::string FdTransport::read(int timeout_ms)
{
	pollfd p{fd_, POLLIN, 0};
	const int r = ::poll(&p, 1, timeout_ms);
	if (r < 0 && errno == EINTR) return {};
	if (r < 0) throw TransportClosed(name_ + ": poll failed: " + std::strerror(errno));
	if (r == 0) return {};
	if (!(p.revents & POLLIN)) throw TransportClosed(name_ + ": the other end hung up");
	char buf[512];
	const ssize_t n = ::read(fd_, buf, sizeof(buf));
	if (n <= 0) throw TransportClosed(name_ + ": the other end hung up");
	return std::string(buf, size_t(n));
}

}  // namespace mrolr::hw_serial
