#include <mrolr/hw_serial/Message.h>
#include <mrolr/hw_serial/SerialClient.h>

#include <chrono>
#include <random>

namespace mrolr::hw_serial
{
namespace
{
using Clock = std::chrono::steady_clock;
using Kind = SerialDeviceError::Kind;

std::string joinText(const std::vector<std::string>& fields, size_t from)
{
	std::string out;
	for (size_t i = from; i < fields.size(); ++i) out += (out.empty() ? "" : " ") + fields[i];
	return out;
}
}  // namespace

SerialClient::SerialClient(std::unique_ptr<ByteTransport> link, const LinkOptions& options)
    : link_(std::move(link)), options_(options), assembler_(options.max_line_bytes)
{
	next_seq_ = options.first_seq;
	if (next_seq_ >= 1 && next_seq_ <= kMaxSeq) return;
	std::random_device entropy;
	next_seq_ = std::uniform_int_distribution<int>(1, kMaxSeq)(entropy);
}

void SerialClient::fail(int kind, const std::string& what) const
{
	throw SerialDeviceError(Kind(kind), options_.device, link_->name(), what);
}

std::vector<std::string> SerialClient::call(const std::string& verb,
                                            const std::vector<std::string>& args, int timeout_ms)
{
	if (timeout_ms <= 0) timeout_ms = options_.timeout_ms;
	const int seq = next_seq_;
	next_seq_ = next_seq_ % kMaxSeq + 1;
	const std::string request = frameLine(formatMessage({seq, verb, args}));
	std::string garbage;
	Outcome last = Outcome::Timeout;
	for (int attempt = 0; attempt <= options_.retries; ++attempt)
	{
		if (attempt > 0) ++resends_;
		Message reply;
		try
		{
			link_->write(request);
			last = awaitReply(seq, timeout_ms, reply, garbage);
		}
		catch (const TransportClosed& e)
		{
			fail(int(Kind::Disconnected), std::string(e.what()) + " (command " + verb + ")");
		}
		if (last != Outcome::Reply) continue;
		if (reply.word == "OK") return reply.fields;
		last_code_ = reply.fields.empty() ? "" : reply.fields[0];
		fail(int(Kind::Refused), "command " + verb + " answered ERR " + joinText(reply.fields, 0));
	}
	const std::string tries = std::to_string(options_.retries + 1) + " attempts of " +
	                          std::to_string(timeout_ms) + " ms (command " + verb + ")";
	if (last == Outcome::Garbage) fail(int(Kind::Garbage), garbage + " after " + tries);
	fail(int(Kind::Timeout), "no reply after " + tries);
}

SerialClient::Outcome SerialClient::awaitReply(int seq, int timeout_ms, Message& reply,
                                               std::string& garbage)
{
	const auto deadline = Clock::now() + std::chrono::milliseconds(timeout_ms);
	for (;;)
	{
		AssembledLine line;
		while (assembler_.next(line))
		{
			const Outcome o = classifyLine(line, seq, reply, garbage);
			if (o != Outcome::Timeout) return o;
		}
		const auto left =
		    std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now()).count();
		if (left <= 0) return Outcome::Timeout;
		assembler_.feed(link_->read(int(left)));
	}
}

// Timeout here means "not this line, keep waiting" (a stale reply to an earlier request).
SerialClient::Outcome SerialClient::classifyLine(const AssembledLine& line, int seq, Message& reply,
                                                 std::string& garbage)
{
	const Unframed u = unframeLine(line.text);
	const ParsedMessage p = u.ok ? parseMessage(u.body) : ParsedMessage{};
	const Message& m = p.message;
	const bool is_err = m.word == "ERR" && !m.fields.empty();
	if (line.overlong || !p.ok || (m.word != "OK" && !is_err))
	{
		garbage = (line.overlong ? "overlong reply '" : "garbage reply '") +
		          printableBytes(line.text) + "'";
		return Outcome::Garbage;
	}
	// a BADLINE answer carries no usable sequence number: our request was damaged on the way
	if (m.seq == kNoSeq || (is_err && m.fields[0] == errcode::kBadLine))
	{
		garbage = "the device could not read the request: '" + printableBytes(u.body) + "'";
		return Outcome::Garbage;
	}
	if (m.seq != seq) return Outcome::Timeout;
	reply = m;
	return Outcome::Reply;
}

}  // namespace mrolr::hw_serial
