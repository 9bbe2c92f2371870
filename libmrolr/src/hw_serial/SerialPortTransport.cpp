#include <mrolr/hw_serial/SerialPortTransport.h>

#include <mrpt/comms/CSerialPort.h>

#include <poll.h>
#include <sys/ioctl.h>

#include <algorithm>

#include <cerrno>
#include <cstring>

namespace mrolr::hw_serial
{
/** CSerialPort with its descriptor visible, for poll(). */
class SerialPortTransport::Port : public mrpt::comms::CSerialPort
{
 public:
	using CSerialPort::CSerialPort;
	int fd() const { return hCOM; }
};

SerialPortTransport::SerialPortTransport(const std::string& port, int baud) : port_(port)
{
	port_impl_ = std::make_unique<Port>(port, false);
	try
	{
		port_impl_->open();
		port_impl_->setConfig(baud, 0, 8, 1, false);
		// a zero total timeout makes CSerialPort::Read return the bytes already waiting; the
		// waiting itself is done with poll() in read()
		port_impl_->setTimeouts(0, 0, 0, 0, 0);
	}
	catch (const std::exception& e)
	{
		throw TransportClosed(port + ": cannot open the serial port at " + std::to_string(baud) +
		                      " baud: " + mrptMessage(e.what()));
	}
}

SerialPortTransport::~SerialPortTransport() = default;

void SerialPortTransport::write(const std::string& bytes)
{
	if (!port_impl_->isOpen()) throw TransportClosed(port_ + ": the port is closed");
	try
	{
		port_impl_->Write(bytes.data(), bytes.size());
	}
	catch (const std::exception& e)
	{
		throw TransportClosed(port_ + ": write failed: " + mrptMessage(e.what()));
	}
}

std::string SerialPortTransport::read(int timeout_ms)
{
	if (!port_impl_->isOpen()) throw TransportClosed(port_ + ": the port is closed");
	pollfd p{port_impl_->fd(), POLLIN, 0};
	const int r = ::poll(&p, 1, timeout_ms);
	if (r < 0 && errno == EINTR) return {};
	if (r < 0) throw TransportClosed(port_ + ": poll failed: " + std::strerror(errno));
	if (r == 0) return {};
	if (p.revents & (POLLHUP | POLLERR | POLLNVAL))
		throw TransportClosed(port_ + ": the device hung up");
	// ask CSerialPort for exactly the bytes waiting: it then returns without its 1 ms nap
	int waiting = 0;
	if (::ioctl(port_impl_->fd(), FIONREAD, &waiting) < 0 || waiting <= 0) waiting = 1;
	char buf[512];
	const size_t n = port_impl_->Read(buf, std::min(sizeof(buf), size_t(waiting)));
	if (!port_impl_->isOpen()) throw TransportClosed(port_ + ": the device was disconnected");
	return std::string(buf, n);
}

}  // namespace mrolr::hw_serial
