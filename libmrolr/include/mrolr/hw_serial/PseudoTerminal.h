#pragma once
/** A pseudo-terminal pair (posix_openpt / grantpt / unlockpt / ptsname) for the device emulators:
 * the emulator talks on the master side, a driver opens slavePath() as if it were a serial port.
 * The slave is put in raw mode and held open, so the master does not see a hang-up between
 * clients. */

#include <mrolr/hw_serial/Transport.h>

#include <memory>

namespace mrolr::hw_serial
{
class PseudoTerminal
{
 public:
	/** Opens a new pair; throws std::runtime_error with errno's text if the system refuses. */
	PseudoTerminal();
	~PseudoTerminal();
	PseudoTerminal(const PseudoTerminal&) = delete;
	PseudoTerminal& operator=(const PseudoTerminal&) = delete;

	/** "/dev/pts/N", the path a serial driver opens. */
	const std::string& slavePath() const { return slave_path_; }
	/** Transport on the master side (valid while this object lives and until hangUp()). */
	ByteTransport& master() { return *master_; }
	/** Closes both sides: every driver on the slave sees a hang-up (a pulled cable). */
	void hangUp();

 private:
	int master_fd_ = -1, slave_fd_ = -1;
	std::string slave_path_;
	std::unique_ptr<FdTransport> master_;
};

}  // namespace mrolr::hw_serial
