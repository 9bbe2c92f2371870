#include <mrolr/hw_serial/Message.h>

#include <charconv>
#include <cmath>
#include <stdexcept>

namespace mrolr::hw_serial
{
namespace
{
std::vector<std::string> splitSpaces(std::string_view body, bool& empty_field)
{
	std::vector<std::string> out;
	empty_field = false;
	size_t start = 0;
	while (start <= body.size())
	{
		const size_t end = std::min(body.find(' ', start), body.size());
		if (end == start) empty_field = true;
		out.emplace_back(body.substr(start, end - start));
		start = end + 1;
	}
	return out;
}

bool parseSeq(const std::string& text, int& seq)
{
	if (text == "-")
	{
		seq = kNoSeq;
		return true;
	}
	if (text.empty() || text.size() > 4 || text[0] == '0') return false;
	for (char c : text)
		if (c < '0' || c > '9') return false;
	seq = std::stoi(text);
	return true;
}

ParsedMessage failure(const std::string& why)
{
	ParsedMessage p;
	p.error = why;
	return p;
}
}  // namespace

ParsedMessage parseMessage(std::string_view body)
{
	bool empty_field = false;
	auto parts = splitSpaces(body, empty_field);
	if (empty_field) return failure("empty field (fields are separated by single spaces)");
	if (parts.size() < 2) return failure("expected 'SEQ WORD ...'");
	ParsedMessage p;
	if (!parseSeq(parts[0], p.message.seq))
		return failure("bad sequence number '" + parts[0] + "' (1.." + std::to_string(kMaxSeq) +
		               " or '-')");
	p.message.word = parts[1];
	p.message.fields.assign(parts.begin() + 2, parts.end());
	p.ok = true;
	return p;
}

std::string formatMessage(const Message& m)
{
	std::string out = m.seq == kNoSeq ? "-" : std::to_string(m.seq);
	out += " " + m.word;
	for (const auto& f : m.fields) out += " " + f;
	return out;
}

std::string formatNumber(double value)
{
	if (!std::isfinite(value))
		throw std::invalid_argument("cannot send a non-finite number over the serial line");
	char buf[32];
	const auto r = std::to_chars(buf, buf + sizeof(buf), value);
	return std::string(buf, r.ptr);
}

std::vector<double> parseNumbers(const std::vector<std::string>& fields, size_t count,
                                 const std::string& what)
{
	if (fields.size() != count)
		throw std::invalid_argument(what + ": expected " + std::to_string(count) +
		                            " numbers, got " + std::to_string(fields.size()) + " fields");
	std::vector<double> out(count);
	for (size_t i = 0; i < count; ++i)
	{
		const auto& f = fields[i];
		const auto r = std::from_chars(f.data(), f.data() + f.size(), out[i]);
		if (f.empty() || r.ec != std::errc() || r.ptr != f.data() + f.size() ||
		    !std::isfinite(out[i]))
			throw std::invalid_argument(what + ": field " + std::to_string(i + 1) + " '" + f +
			                            "' is not a finite number");
	}
	return out;
}

long parseInteger(const std::string& field, const std::string& what)
{
	long v = 0;
	const char* b = field.data();
	const char* e = b + field.size();
	const auto r = std::from_chars(b, e, v);
	if (field.empty() || r.ec != std::errc() || r.ptr != e)
		throw std::invalid_argument(what + ": '" + field + "' is not an integer");
	return v;
}

}  // namespace mrolr::hw_serial
