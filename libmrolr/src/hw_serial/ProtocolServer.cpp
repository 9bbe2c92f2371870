#include <mrolr/geometry/GeometryError.h>
#include <mrolr/hw/Devices.h>
#include <mrolr/hw_serial/Message.h>
#include <mrolr/hw_serial/ProtocolServer.h>

namespace mrolr::hw_serial
{
namespace
{
/** Error text as protocol words: printable, no '*', bounded length. */
std::vector<std::string> errorFields(const std::string& code, const std::string& text)
{
	std::string clean;
	for (char c : text.substr(0, 150)) clean += (c >= 0x21 && c <= 0x7e && c != '*') ? c : ' ';
	std::vector<std::string> fields{code};
	size_t start = 0;
	while (start < clean.size())
	{
		const size_t end = std::min(clean.find(' ', start), clean.size());
		if (end > start) fields.push_back(clean.substr(start, end - start));
		start = end + 1;
	}
	return fields;
}

std::string errorReply(int seq, const std::string& code, const std::string& text)
{
	return frameLine(formatMessage({seq, "ERR", errorFields(code, text)}));
}
}  // namespace

std::string ProtocolServer::handleLine(const AssembledLine& line)
{
	if (line.overlong) return errorReply(kNoSeq, errcode::kBadLine, "line too long");
	const Unframed u = unframeLine(line.text);
	if (!u.ok) return errorReply(kNoSeq, errcode::kBadLine, u.error);
	const ParsedMessage p = parseMessage(u.body);
	if (!p.ok || p.message.seq == kNoSeq)
		return errorReply(kNoSeq, errcode::kBadLine,
		                  p.ok ? "request without sequence number" : p.error);
	if (u.body == last_request_) return last_reply_;  // a resend: do not execute twice
	last_reply_ = execute(p.message.seq, p.message.word, p.message.fields);
	last_request_ = u.body;
	return last_reply_;
}

std::string ProtocolServer::execute(int seq, const std::string& verb,
                                    const std::vector<std::string>& args)
{
	++executed_;
	try
	{
		return frameLine(formatMessage({seq, "OK", handler_.execute(verb, args)}));
	}
	catch (const CommandError& e)
	{
		return errorReply(seq, e.code(), e.what());
	}
	catch (const std::out_of_range& e)
	{
		return errorReply(seq, errcode::kLimit, e.what());
	}
	catch (const geometry::FixationError& e)
	{
		return errorReply(seq, errcode::kLimit, e.what());
	}
	catch (const hw::ArmBlocked& e)
	{
		return errorReply(seq, errcode::kBlocked, e.what());
	}
	catch (const std::exception& e)
	{
		return errorReply(seq, errcode::kFault, e.what());
	}
}

}  // namespace mrolr::hw_serial
