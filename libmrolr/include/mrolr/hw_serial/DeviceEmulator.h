#pragma once
/** A device emulator: serves a RequestHandler's protocol on a byte transport from its own thread,
 * with injectable faults, so that the serial drivers can be run through real serial I/O against
 * the simulated devices (PtyEmulator puts it on a pseudo-terminal). */

#include <mrolr/hw_serial/DeviceProtocols.h>
#include <mrolr/hw_serial/Framing.h>
#include <mrolr/hw_serial/PseudoTerminal.h>
#include <mrolr/hw_serial/Transport.h>

#include <atomic>
#include <memory>
#include <mutex>
#include <random>
#include <thread>

namespace mrolr::hw_serial
{
class ProtocolServer;

/** Faults applied to the emulator's replies (all off by default). */
struct FaultOptions
{
	int reply_delay_ms = 0;            ///< every reply is sent this late
	int drop_byte_replies = 0;         ///< the next N replies lose one byte in their middle
	int garbage_replies = 0;           ///< the next N replies are replaced by binary garbage
	double drop_byte_probability = 0;  ///< each byte of every reply is lost with this chance
	bool silent = false;  ///< requests are read, neither executed nor answered (a hung device)
	/** -1: off; N >= 0: the device answers N more requests, then goes silent (hangs mid-run). */
	int silent_after_replies = -1;
	unsigned seed = 1;    ///< for drop_byte_probability
};

class DeviceEmulator
{
 public:
	/** Starts serving @p handler on @p link (both must outlive the emulator). */
	DeviceEmulator(ByteTransport& link, RequestHandler& handler, const FaultOptions& faults = {});
	~DeviceEmulator();
	DeviceEmulator(const DeviceEmulator&) = delete;
	DeviceEmulator& operator=(const DeviceEmulator&) = delete;

	/** Replaces the faults from now on (thread-safe). */
	void setFaults(const FaultOptions& faults);
	/** Stops the thread and waits for it (at most one poll period plus a pending reply delay). */
	void stop();
	/** Requests executed so far (resends answered from the cache not counted). */
	size_t executed() const { return executed_; }
	/** Lines received so far. */
	size_t received() const { return received_; }

 private:
	void loop();
	void serveLine(ProtocolServer& server, const AssembledLine& line);
	std::string applyFaults(std::string reply, int& delay_ms);
	bool silent();
	void sleepUnlessStopped(int ms) const;

	ByteTransport& link_;
	RequestHandler& handler_;
	std::mutex mutex_;
	FaultOptions faults_;
	std::mt19937 rng_;
	std::atomic<bool> stop_{false};
	std::atomic<size_t> executed_{0}, received_{0};
	std::thread thread_;
};

/** A device emulator on its own pseudo-terminal: open slavePath() with a serial driver. */
class PtyEmulator
{
 public:
	PtyEmulator(RequestHandler& handler, const FaultOptions& faults = {})
	    : emulator_(pty_.master(), handler, faults)
	{
	}
	const std::string& slavePath() const { return pty_.slavePath(); }
	DeviceEmulator& emulator() { return emulator_; }
	/** Stops serving and closes the pseudo-terminal: drivers see a disconnect. */
	void hangUp()
	{
		emulator_.stop();
		pty_.hangUp();
	}

 private:
	PseudoTerminal pty_;
	DeviceEmulator emulator_;
};

}  // namespace mrolr::hw_serial
