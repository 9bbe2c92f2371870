#include <mrolr/hw_serial/Framing.h>

#include <mrpt/system/crc.h>

#include <cstdio>

namespace mrolr::hw_serial
{
namespace
{
bool printable(char c)
{
	return c >= 0x20 && c <= 0x7e;
}

int hexValue(char c)
{
	if (c >= '0' && c <= '9') return c - '0';
	if (c >= 'A' && c <= 'F') return c - 'A' + 10;
	return -1;
}
}  // namespace

constexpr size_t kCrcDigits = 8;

uint32_t lineChecksum(std::string_view body)
{
	if (body.empty()) return 0;
	return mrpt::system::compute_CRC32(reinterpret_cast<const uint8_t*>(body.data()), body.size());
}

std::string frameLine(std::string_view body)
{
	char tail[kCrcDigits + 2];
	std::snprintf(tail, sizeof(tail), "*%08X", unsigned(lineChecksum(body)));
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
	if (star == std::string_view::npos || star + 1 + kCrcDigits != line.size())
	{
		u.error = "no checksum at the end of the line";
		return u;
	}
	uint32_t crc = 0;
	for (size_t i = star + 1; i < line.size(); ++i)
	{
		const int h = hexValue(line[i]);
		if (h < 0)
		{
			u.error = "checksum is not upper-case hex";
			return u;
		}
		crc = crc * 16 + uint32_t(h);
	}
	const auto body = line.substr(0, star);
	if (lineChecksum(body) != crc)
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

}  // namespace mrolr::hw_serial
