#pragma once
/** A configuration file as MROLR reads it: MRPT's `.ini` format, plus one rule, a base file. A file
 * whose `[base]` section has `file = OTHER.ini` (relative to its own folder) is that file with its
 * own keys laid over it: a key given in both takes this file's value, every other key of the base
 * stands. Bases may have bases; a cycle or a missing base is a ConfigError naming the file that
 * named it. The mission files share `config/mission.ini` this way (docs/config.md "Base files").
 *
 * Relative paths inside a base file are read against the folder of the file that was opened, not
 * the base's: keep a base beside the files that use it. Error messages name the file that gave the
 * key (util::describeKey). */

#include <mrpt/config/CConfigFileMemory.h>

#include <map>
#include <string>
#include <utility>
#include <vector>

namespace mrolr::util
{
class ConfigFile : public mrpt::config::CConfigFileMemory
{
 public:
	/** Reads @p path and its bases; ConfigError when a file cannot be read or the chain loops. */
	static ConfigFile load(const std::string& path, const std::string& named_by = "");

	/** The file that was opened (the top of the chain). */
	const std::string& path() const { return path_; }
	/** The file whose value of [section] key stands; path() for a key not in any file (one
	 * written afterwards, e.g. a command-line override). */
	const std::string& fileOf(const std::string& section, const std::string& key) const;
	/** Writes a value given outside the files (a `--set`); messages name it by @p origin. */
	void set(const std::string& section, const std::string& key, const std::string& value,
	         const std::string& origin);
	/** The files read, the opened one first, then its base, its base's base... */
	const std::vector<std::string>& chain() const { return chain_; }

 private:
	std::string path_;
	std::vector<std::string> chain_;
	std::map<std::pair<std::string, std::string>, std::string> origin_;
};

}  // namespace mrolr::util
