#include <mrolr/hw_serial/PseudoTerminal.h>

#include <fcntl.h>
#include <termios.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <stdexcept>

namespace mrolr::hw_serial
{
namespace
{
[[noreturn]] void fail(const std::string& what)
{
	throw std::runtime_error("pseudo-terminal: " + what + ": " + std::strerror(errno));
}
}  // namespace

PseudoTerminal::PseudoTerminal()
{
	master_fd_ = ::posix_openpt(O_RDWR | O_NOCTTY);
	if (master_fd_ < 0) fail("posix_openpt");
	char name[128];
	if (::grantpt(master_fd_) != 0 || ::unlockpt(master_fd_) != 0 ||
	    ::ptsname_r(master_fd_, name, sizeof(name)) != 0)
	{
		::close(master_fd_);
		fail("grantpt/unlockpt/ptsname");
	}
	slave_path_ = name;
	slave_fd_ = ::open(name, O_RDWR | O_NOCTTY);
	termios t{};
	if (slave_fd_ < 0 || ::tcgetattr(slave_fd_, &t) != 0)
	{
		::close(master_fd_);
		fail("opening " + slave_path_);
	}
	::cfmakeraw(&t);  // no echo, no line editing, no CR/LF translation
	::tcsetattr(slave_fd_, TCSANOW, &t);
	master_ = std::make_unique<FdTransport>(master_fd_, "pty master of " + slave_path_);
}

PseudoTerminal::~PseudoTerminal()
{
	hangUp();
}

void PseudoTerminal::hangUp()
{
	if (slave_fd_ >= 0) ::close(slave_fd_);
	if (master_fd_ >= 0) ::close(master_fd_);
	slave_fd_ = master_fd_ = -1;
}

}  // namespace mrolr::hw_serial
