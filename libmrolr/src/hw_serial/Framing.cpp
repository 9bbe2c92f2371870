#include <mrolr/hw_serial/Framing.h>

#include <cstdio>

namespace mrolr::hw
{
namespace
{
bool printable(char c) { return c >= 0x20 && c <= 0x7e; }

int hexValue(char c)
{
	if (c >= '0' && c <= '9') return c - '0';
	if (c >= 'A' && c <= 'F') return c - 'A' + 10;
	return -1;
}
}  // namespace

uint8_t lineChecksum(std::string_view body)
{
	uint8_t x = 0;
	for (char c : body) x ^= uint8_t(c);
	return x;
}

std::string frameLine(std::string_view body)
{
	char tail[5];
	std::snprintf(tail, sizeof(tail), "*%02X", unsigned(lineChecksum(body)));
	return std::string(body) + tail + "\n";
}

Unframed unframeLine(std::string_view line)
{
	Unframed u;
	if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
	for (char c : line)
		if (!printable(c))
		{
			u.error = "non-printable byte in line";
			return u;
		}
	const size_t star = line.rfind('*');
	if (star == std::string_view::npos || star + 3 != line.size())
	{
		u.error = "no checksum at the end of the line";
		return u;
	}
	const int hi = hexValue(line[star + 1]), lo = hexValue(line[star + 2]);
	const auto body = line.substr(0, star);
	if (hi < 0 || lo < 0 || lineChecksum(body) != uint8_t(hi * 16 + lo))
	{
		u.error = "checksum mismatch";
		return u;
	}
	u.ok = true;
	u.body = std::string(body);
	return u;
}

std::string printableBytes(std::string_view bytes, size_t max_chars)
{
	std::string out;
	for (char c : bytes)
	{
		if (out.size() >= max_chars) return out + "...";
		if (printable(c) && c != '\\')
			out += c;
		else
		{
			char hex[5];
			std::snprintf(hex, sizeof(hex), "\\x%02X", unsigned(uint8_t(c)));
			out += hex;
		}
	}
	return out;
}

void LineAssembler::feed(std::string_view bytes)
{
	for (char c : bytes) push(c);
}

void LineAssembler::push(char c)
{
	if (c == '\n')
	{
		if (!skipping_) lines_.push_back({partial_, false});
		partial_.clear();
		skipping_ = false;
		return;
	}
	if (skipping_) return;
	if (partial_.size() < max_)
	{
		partial_ += c;
		return;
	}
	lines_.push_back({partial_, true});
	partial_.clear();
	skipping_ = true;
}

bool LineAssembler::next(AssembledLine& out)
{
	if (lines_.empty()) return false;
	out = std::move(lines_.front());
	lines_.pop_front();
	return true;
}

void LineAssembler::clear()
{
	partial_.clear();
	skipping_ = false;
	lines_.clear();
}

}  // namespace mrolr::hw
