#pragma once
/** An `.ini` file read in file order. MRPT's CConfigFile keeps keys in a map, but a route's
 * waypoints (a world's, a plan's) are an order that matters, so such files are read with this
 * small reader; it keeps every key's line number so that errors can name file, section, key, value
 * and line. */

#include <stdexcept>
#include <string>
#include <vector>

namespace mrolr::util
{
/** Thrown for any malformed file read this way; what() names file, line, section, key and
 * value. */
class IniError : public std::runtime_error
{
 public:
	using std::runtime_error::runtime_error;
};

/** One `key = value` line. */
struct IniEntry
{
	std::string key;
	std::string value;
	int line = 0;  ///< 1-based line number in the file
};

/** One `[section]` with its entries in file order. */
struct IniSection
{
	std::string name;
	int line = 0;
	std::vector<IniEntry> entries;
	/** The entry with this key, or nullptr. */
	const IniEntry* find(const std::string& key) const;
};

/** A whole file: sections in file order. Comments start with '#' or ';' (whole line or after
 * whitespace); a repeated section or key is an error. */
struct IniDocument
{
	std::string path;
	std::vector<IniSection> sections;

	/** Reads @p path; throws IniError (naming file and line) if unreadable or malformed. */
	static IniDocument load(const std::string& path);
	/** Parses @p text as if read from a file called @p path. */
	static IniDocument parse(const std::string& text, const std::string& path);
	/** The section with this name, or nullptr. */
	const IniSection* find(const std::string& name) const;
	/** Replaces the value of @p key in @p section, or appends the key (and the section) when
	 * absent: a command-line override (`--set`); its line number is 0 and messages say so. */
	void set(const std::string& section, const std::string& key, const std::string& value);
	/** "FILE:LINE [SECTION] KEY = 'VALUE'" for error messages. */
	std::string describe(const IniSection& s, const IniEntry& e) const;
	/** Throws IniError "FILE:LINE [SECTION] KEY = 'VALUE': why". */
	[[noreturn]] void fail(const IniSection& s, const IniEntry& e, const std::string& why) const;
};

}  // namespace mrolr::util
