#pragma once
/** Messages of the MROLR serial protocols (docs/serial.md), inside the framing of Framing.h.
 * Request body: `SEQ VERB ARG...`; reply body: `SEQ OK FIELD...` or `SEQ ERR CODE TEXT...`, with
 * SEQ the request's sequence number (1..9999) echoed, or `-` when the device could not read the
 * request at all. Fields are separated by single spaces. Pure functions, no I/O. */

#include <string>
#include <string_view>
#include <vector>

namespace mrolr::hw_serial
{
/** Sequence number of a reply to an unreadable request (`-` on the wire). */
constexpr int kNoSeq = -1;
constexpr int kMaxSeq = 9999;

/** One request or reply: for a reply, word is "OK" or "ERR" (then fields = CODE, text words). */
struct Message
{
	int seq = kNoSeq;
	std::string word;
	std::vector<std::string> fields;
};

/** Error codes of `ERR` replies. */
namespace errcode
{
constexpr const char* kBadLine = "BADLINE";  ///< framing or checksum wrong: resend
constexpr const char* kBadCmd = "BADCMD";    ///< unknown verb
constexpr const char* kBadArg = "BADARG";    ///< wrong field count or a field not a number
constexpr const char* kLimit = "LIMIT";      ///< the device refused: joint or workspace limit
constexpr const char* kFault = "FAULT";      ///< the device failed while executing
constexpr const char* kBlocked = "BLOCKED";  ///< the arm stopped against something on the way
}  // namespace errcode

/** Result of parsing a body. */
struct ParsedMessage
{
	bool ok = false;
	Message message;
	std::string error;
};

/** Parses `SEQ WORD FIELD...` strictly (SEQ 1..9999 or `-`, WORD non-empty, no empty fields). */
ParsedMessage parseMessage(std::string_view body);

/** `SEQ WORD FIELD...` (SEQ `-` for kNoSeq). */
std::string formatMessage(const Message& m);

/** Shortest decimal text that reads back as exactly @p value (std::to_chars); throws
 * std::invalid_argument for NaN or infinity, which the protocols never carry. */
std::string formatNumber(double value);

/** Reads exactly @p count finite numbers from @p fields; throws std::invalid_argument naming
 * @p what, the field count or the bad field. */
std::vector<double> parseNumbers(const std::vector<std::string>& fields, size_t count,
                                 const std::string& what);

/** Strict decimal integer (optional sign, digits only); throws std::invalid_argument naming
 * @p what. */
long parseInteger(const std::string& field, const std::string& what);

}  // namespace mrolr::hw_serial
