#pragma once
/** A ByteTransport on mrpt::comms::CSerialPort: the port is opened and configured by MRPT
 * (8N1, no flow control, the given baud rate); waiting for bytes uses poll() on the port's
 * descriptor so that a hang-up (a pulled USB adapter, a closed pseudo-terminal) is reported as
 * TransportClosed instead of an endless timeout. */

#include <mrolr/hw_serial/Transport.h>

#include <memory>

namespace mrpt::comms
{
class CSerialPort;
}

namespace mrolr::hw_serial
{
class SerialPortTransport : public ByteTransport
{
 public:
	/** Opens @p port at @p baud; throws TransportClosed naming the port if it cannot. */
	SerialPortTransport(const std::string& port, int baud);
	~SerialPortTransport() override;
	void write(const std::string& bytes) override;
	std::string read(int timeout_ms) override;
	std::string name() const override { return port_; }

 private:
	class Port;
	std::unique_ptr<Port> port_impl_;
	std::string port_;
};

}  // namespace mrolr::hw_serial
