#pragma once
/** Strict reading of `.ini` values. Every MROLR options struct reads its keys through these helpers
 * so that a missing or malformed key is reported with the file, the section and the key, instead of
 * MRPT's silent default of 0 for unparsable numbers. */

#include <mrolr/util/ConfigFile.h>

#include <mrpt/config/CConfigFile.h>
#include <mrpt/config/CConfigFileBase.h>

#include <stdexcept>
#include <string>
#include <vector>

namespace mrolr::util
{
/** Thrown for a missing or malformed configuration value; what() names file, section and key. */
class ConfigError : public std::runtime_error
{
   public:
	using std::runtime_error::runtime_error;
};

/** The `.ini` file @p path with its base files (ConfigFile.h), which must be readable (MRPT's
 * CConfigFile reads a missing file as an empty one); ConfigError "cannot open 'PATH'", with
 * " (named by WHAT)" when @p named_by says which key or option gave the path. */
ConfigFile openConfigFile(const std::string& path, const std::string& named_by = "");

/** "FILE [SECTION] KEY" for messages: the file that gave the key (for a ConfigFile, the base that
 * holds it); "<memory>" for a plain CConfigFileMemory. */
std::string describeKey(
	const mrpt::config::CConfigFileBase& cfg, const std::string& section, const std::string& key);

/** True when the key exists in the section (even with an empty value). */
bool hasKey(
	const mrpt::config::CConfigFileBase& cfg, const std::string& section, const std::string& key);

/** Raw string value; throws ConfigError if the key is missing. */
std::string readString(
	const mrpt::config::CConfigFileBase& cfg, const std::string& section, const std::string& key);

/** Number parsed strictly (the whole value must be a finite number); throws ConfigError when the key
 * is missing or the value is not a number. */
double readDouble(
	const mrpt::config::CConfigFileBase& cfg, const std::string& section, const std::string& key);

/** As readDouble, but returns @p fallback when the key is absent (a present, malformed value still
 * throws). */
double readDouble(
	const mrpt::config::CConfigFileBase& cfg, const std::string& section, const std::string& key,
	double fallback);

/** Integer parsed strictly; throws ConfigError when missing or malformed. */
long readInt(
	const mrpt::config::CConfigFileBase& cfg, const std::string& section, const std::string& key);
long readInt(
	const mrpt::config::CConfigFileBase& cfg, const std::string& section, const std::string& key,
	long fallback);

/** Boolean: true/false, yes/no, on/off, 1/0 (case-insensitive). */
bool readBool(
	const mrpt::config::CConfigFileBase& cfg, const std::string& section, const std::string& key,
	bool fallback);

/** Whitespace- or comma-separated numbers; @p expected_count = 0 accepts any count. */
std::vector<double> readDoubles(
	const mrpt::config::CConfigFileBase& cfg, const std::string& section, const std::string& key,
	size_t expected_count = 0);

/** Parses a whole string as a finite double; returns false on any trailing garbage. */
bool parseDouble(const std::string& text, double& out);

/** Splits on whitespace and commas; empty fields are dropped. */
std::vector<std::string> splitFields(const std::string& text);

/** Throws ConfigError naming the key unless lo <= value <= hi. */
void requireInRange(
	const mrpt::config::CConfigFileBase& cfg, const std::string& section, const std::string& key,
	double value, double lo, double hi);

/** readDouble, then requireInRange(lo, hi): the common "number within limits" key. */
double readDoubleInRange(
	const mrpt::config::CConfigFileBase& cfg, const std::string& section, const std::string& key,
	double lo, double hi);

}  // namespace mrolr::util
