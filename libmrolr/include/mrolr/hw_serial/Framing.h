#pragma once
/** Line framing of the MROLR serial protocols (docs/serial.md): every line is printable ASCII,
 * `BODY*CCCCCCCC\n`, where CCCCCCCC is the CRC-32 of the bytes of BODY as eight upper-case hex
 * digits (mrpt::system::compute_CRC32: reflected polynomial 0xEDB88320, initial value 0, no final
 * XOR; "123456789" gives 2DFD2D88). Dropped or damaged bytes therefore show up as a bad checksum
 * instead of a wrong number (an NMEA-style XOR misses two equal dropped bytes, which the pty test
 * with random byte loss did hit). Pure functions, no I/O. */

#include <cstdint>
#include <deque>
#include <string>
#include <string_view>

namespace mrolr::hw_serial
{
/** CRC-32 of the bytes of @p body (0 for an empty body). */
uint32_t lineChecksum(std::string_view body);

/** `body*CCCCCCCC\n`. */
std::string frameLine(std::string_view body);

/** Result of checking one received line (without its '\n'). */
struct Unframed
{
	bool ok = false;
	std::string body;   ///< the text before '*' when ok
	std::string error;  ///< why the line was rejected, when !ok
};

/** Checks printable ASCII, the `*CCCCCCCC` suffix and the checksum; a trailing '\r' is
 * tolerated. */
Unframed unframeLine(std::string_view line);

/** @p bytes with non-printable bytes as \xHH, cut to @p max_chars (for error messages). */
std::string printableBytes(std::string_view bytes, size_t max_chars = 60);

/** One line assembled from the byte stream. */
struct AssembledLine
{
	std::string text;       ///< without '\n' (only the first max_line_bytes when overlong)
	bool overlong = false;  ///< the line exceeded the limit and its rest was discarded
};

/** Reassembles lines from bytes that arrive in arbitrary pieces. A line longer than the limit is
 * reported once as overlong and its remaining bytes are skipped up to the next '\n', so a stream of
 * garbage never grows the buffer without bound. */
class LineAssembler
{
 public:
	explicit LineAssembler(size_t max_line_bytes = 256) : max_(max_line_bytes) {}
	void feed(std::string_view bytes);
	/** Pops the next complete line; false when none is complete yet. */
	bool next(AssembledLine& out);
	/** Drops buffered bytes and lines (after a resynchronisation). */
	void clear();
	/** Bytes of the incomplete line held so far. */
	size_t pendingBytes() const { return partial_.size(); }

 private:
	void push(char c);

	size_t max_;
	std::string partial_;
	bool skipping_ = false;
	std::deque<AssembledLine> lines_;
};

}  // namespace mrolr::hw_serial
