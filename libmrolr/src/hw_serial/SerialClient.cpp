#include <mrolr/hw_serial/Message.h>
#include <mrolr/hw_serial/SerialClient.h>

#include <chrono>

namespace mrolr::hw
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
}

void SerialClient::fail(int kind, const std::string& what) const
{
	throw SerialDeviceError(Kind(kind), options_.device, link_->name(), what);
}

std::vector<std::string> SerialClient::call(const std::string& verb,
                                            const std::vector<std::string>& args)
{
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
			last = awaitReply(seq, reply, garbage);
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
	                          std::to_string(options_.timeout_ms) + " ms (command " + verb + ")";
	if (last == Outcome::Garbage)
		fail(int(Kind::Garbage), "garbage reply '" + printableBytes(garbage) + "' after " + tries);
	fail(int(Kind::Timeout), "no reply after " + tries);
}

SerialClient::Outcome SerialClient::awaitReply(int seq, Message& reply, std::string& garbage)
{
	const auto deadline = Clock::now() + std::chrono::milliseconds(options_.timeout_ms);
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
	const bool reply_word = p.ok && (p.message.word == "OK" || p.message.word == "ERR");
	const bool device_lost_request = reply_word && p.message.seq == kNoSeq;
	if (line.overlong || !reply_word || device_lost_request ||
	    (p.message.word == "ERR" && p.message.fields.empty()))
	{
		garbage = line.text + (line.overlong ? "...(overlong)" : "");
		return Outcome::Garbage;
	}
	if (p.message.seq != seq) return Outcome::Timeout;
	if (p.message.word == "ERR" && p.message.fields[0] == errcode::kBadLine)
	{
		garbage = line.text;
		return Outcome::Garbage;
	}
	reply = p.message;
	return Outcome::Reply;
}

}  // namespace mrolr::hw
