#pragma once
/** An in-memory byte pipe for tests, as MRPT's CGPSInterface_unittest swaps the serial port for a
 * stream: two connected ends, each a ByteTransport; closing either end makes both report
 * TransportClosed. Thread-safe. */

#include <mrolr/hw_serial/Transport.h>

#include <memory>
#include <utility>

namespace mrolr::hw_serial
{
class MemoryTransport : public ByteTransport
{
 public:
	struct Shared;
	MemoryTransport(std::shared_ptr<Shared> shared, int side)
	    : shared_(std::move(shared)), side_(side)
	{
	}
	void write(const std::string& bytes) override;
	std::string read(int timeout_ms) override;
	std::string name() const override { return "memory"; }
	/** Closes the pipe for both ends (a disconnect). */
	void close();

 private:
	std::shared_ptr<Shared> shared_;
	int side_;
};

/** Two connected ends: what one writes, the other reads. */
std::pair<std::unique_ptr<MemoryTransport>, std::unique_ptr<MemoryTransport>> makeMemoryPipe();

}  // namespace mrolr::hw_serial
