#pragma once
/** An `.ini` file read in file order. MRPT's CConfigFile keeps keys in a map, but a world's
 * waypoints are a route whose order matters, so world files are read with this small reader; it
 * keeps every key's line number so that errors can name file, section, key, value and line. */

#include <stdexcept>
#include <string>
#include <vector>

namespace mrolr::world
{
/** Thrown for any malformed world description; what() names file, section, key and value. */
class WorldError : public std::runtime_error
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

	/** Reads @p path; throws WorldError (naming file and line) if unreadable or malformed. */
	static IniDocument load(const std::string& path);
	/** Parses @p text as if read from a file called @p path. */
	static IniDocument parse(const std::string& text, const std::string& path);
	/** The section with this name, or nullptr. */
	const IniSection* find(const std::string& name) const;
	/** "FILE:LINE [SECTION] KEY = 'VALUE'" for error messages. */
	std::string describe(const IniSection& s, const IniEntry& e) const;
	/** Throws WorldError "FILE:LINE [SECTION] KEY = 'VALUE': why". */
	[[noreturn]] void fail(const IniSection& s, const IniEntry& e, const std::string& why) const;
};

}  // namespace mrolr::world
