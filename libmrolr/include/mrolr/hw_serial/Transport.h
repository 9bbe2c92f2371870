#pragma once
/** Byte transports under the serial drivers and the device emulators: a real serial port
 * (SerialPortTransport, on mrpt::comms::CSerialPort), a pseudo-terminal master (PseudoTerminal)
 * and an in-memory pipe for tests (MemoryTransport). */

#include <mrolr/hw_serial/SerialError.h>

#include <string>

namespace mrolr::hw_serial
{
class ByteTransport
{
 public:
	virtual ~ByteTransport() = default;
	/** Writes all of @p bytes; throws TransportClosed when the other end has gone. */
	virtual void write(const std::string& bytes) = 0;
	/** Waits at most @p timeout_ms for bytes and returns those that arrived (empty on timeout);
	 * throws TransportClosed when the other end has gone. */
	virtual std::string read(int timeout_ms) = 0;
	/** The port's name for messages ("/dev/ttyUSB0", "memory"). */
	virtual std::string name() const = 0;
};

/** A transport over a POSIX file descriptor (poll + read/write); it does not own the descriptor. */
class FdTransport : public ByteTransport
{
 public:
	FdTransport(int fd, std::string name) : fd_(fd), name_(std::move(name)) {}
	void write(const std::string& bytes) override;
	std::string read(int timeout_ms) override;
	std::string name() const override { return name_; }

 private:
	int fd_;
	std::string name_;
};

}  // namespace mrolr::hw_serial
