#pragma once
/** The framing and bookkeeping a device does around its RequestHandler: checks a received line,
 * answers a repeated sequence number from its cache without executing again, and turns every
 * failure into an `ERR` reply (a bad line → `- ERR BADLINE`, the device's std::out_of_range or
 * geometry::FixationError → `LIMIT`, anything else → `FAULT`). Pure: line in, framed reply out. */

#include <mrolr/hw_serial/DeviceProtocols.h>
#include <mrolr/hw_serial/Framing.h>

#include <string>

namespace mrolr::hw_serial
{
class ProtocolServer
{
 public:
	explicit ProtocolServer(RequestHandler& handler) : handler_(handler) {}

	/** The framed reply (`...*HH\n`) to one received line. */
	std::string handleLine(const AssembledLine& line);
	/** Requests executed (a repeat answered from the cache does not count). */
	size_t executed() const { return executed_; }

 private:
	std::string execute(int seq, const std::string& verb, const std::vector<std::string>& args);

	RequestHandler& handler_;
	std::string last_request_;  ///< body of the last executed request (sequence number included)
	std::string last_reply_;
	size_t executed_ = 0;
};

}  // namespace mrolr::hw_serial
