#pragma once
/** The host side of a serial protocol: sends one request at a time and waits for its reply, with a
 * timeout per attempt and a bounded number of retries (docs/serial.md "Retries").
 *
 * Every request carries a sequence number that the device echoes and remembers: a resent request
 * (same number) is answered from the device's cache and not executed twice, so retrying a STEP or a
 * MOVE whose reply was lost is safe. Replies with another number (late answers to an earlier
 * attempt) are skipped. */

#include <mrolr/hw_serial/Framing.h>
#include <mrolr/hw_serial/Message.h>
#include <mrolr/hw_serial/Transport.h>

#include <memory>
#include <string>
#include <vector>

namespace mrolr::hw_serial
{
/** Link parameters of one device (section [device.*] of config/mission_hw.ini). */
struct LinkOptions
{
	std::string device = "device";  ///< name used in error messages (the config section)
	int timeout_ms = 500;           ///< wait for a reply, per attempt
	int motion_timeout_ms = 5000;   ///< wait for the reply to a motion (head or arm MOVE)
	int retries = 3;                ///< resends after the first attempt
	size_t max_line_bytes = 256;    ///< longer lines are rejected as garbage
	/** First sequence number; 0 draws it at random, so that a host that reconnects does not
	 * repeat the number (and the body) of the device's last request, which the device would take
	 * for a resend and answer from its cache. */
	int first_seq = 0;
};

class SerialClient
{
 public:
	SerialClient(std::unique_ptr<ByteTransport> link, const LinkOptions& options);

	/** Sends `VERB ARGS...` and returns the fields of the `OK` reply. Throws SerialDeviceError:
	 * Refused for an `ERR` other than BADLINE (what() has the code and the device's text),
	 * Timeout or Garbage when every attempt failed, Disconnected at once when the link closes.
	 * @p timeout_ms overrides options().timeout_ms for this call (a motion that takes time). */
	std::vector<std::string> call(const std::string& verb, const std::vector<std::string>& args,
	                              int timeout_ms = 0);

	/** The code of the last Refused error (e.g. "LIMIT"), for drivers that map it. */
	const std::string& lastErrorCode() const { return last_code_; }
	const LinkOptions& options() const { return options_; }
	std::string portName() const { return link_->name(); }
	/** Attempts that had to be resent so far (for reports and tests). */
	int resends() const { return resends_; }

 private:
	enum class Outcome
	{
		Reply,
		Timeout,
		Garbage
	};
	Outcome awaitReply(int seq, int timeout_ms, Message& reply, std::string& garbage);
	Outcome classifyLine(const AssembledLine& line, int seq, Message& reply, std::string& garbage);
	[[noreturn]] void fail(int kind, const std::string& what) const;

	std::unique_ptr<ByteTransport> link_;
	LinkOptions options_;
	LineAssembler assembler_;
	int next_seq_ = 1;
	int resends_ = 0;
	std::string last_code_;
};

}  // namespace mrolr::hw_serial
