#include <mrolr/util/Config.h>

#include <mrpt/config/CConfigFile.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>

namespace mrolr::util
{
namespace
{
std::string fileNameOf(const mrpt::config::CConfigFileBase& cfg, const std::string& section,
                       const std::string& key)
{
	if (const auto* f = dynamic_cast<const ConfigFile*>(&cfg)) return f->fileOf(section, key);
	if (const auto* f = dynamic_cast<const mrpt::config::CConfigFile*>(&cfg))
		return f->getAssociatedFile();
	return "<memory>";
}

std::string trim(const std::string& s)
{
	const auto b = s.find_first_not_of(" \t\r\n");
	if (b == std::string::npos) return {};
	const auto e = s.find_last_not_of(" \t\r\n");
	return s.substr(b, e - b + 1);
}

[[noreturn]] void fail(
	const mrpt::config::CConfigFileBase& cfg, const std::string& section, const std::string& key,
	const std::string& why)
{
	throw ConfigError(describeKey(cfg, section, key) + ": " + why);
}
}  // namespace

ConfigFile openConfigFile(const std::string& path, const std::string& named_by)
{
	return ConfigFile::load(path, named_by);
}

std::string describeKey(
	const mrpt::config::CConfigFileBase& cfg, const std::string& section, const std::string& key)
{
	return fileNameOf(cfg, section, key) + " [" + section + "] " + key;
}

bool hasKey(
	const mrpt::config::CConfigFileBase& cfg, const std::string& section, const std::string& key)
{
	std::vector<std::string> keys;
	cfg.getAllKeys(section, keys);
	return std::find(keys.begin(), keys.end(), key) != keys.end();
}

std::string readString(
	const mrpt::config::CConfigFileBase& cfg, const std::string& section, const std::string& key)
{
	if (!hasKey(cfg, section, key)) fail(cfg, section, key, "missing key");
	return trim(cfg.read_string(section, key, ""));
}

bool parseDouble(const std::string& text, double& out)
{
	const std::string t = trim(text);
	if (t.empty()) return false;
	errno = 0;
	char* end = nullptr;
	const double v = std::strtod(t.c_str(), &end);
	if (errno != 0 || end != t.c_str() + t.size() || !std::isfinite(v)) return false;
	out = v;
	return true;
}

double readDouble(
	const mrpt::config::CConfigFileBase& cfg, const std::string& section, const std::string& key)
{
	const std::string s = readString(cfg, section, key);
	double v = 0;
	if (!parseDouble(s, v)) fail(cfg, section, key, "'" + s + "' is not a number");
	return v;
}

double readDouble(
	const mrpt::config::CConfigFileBase& cfg, const std::string& section, const std::string& key,
	double fallback)
{
	return hasKey(cfg, section, key) ? readDouble(cfg, section, key) : fallback;
}

long readInt(
	const mrpt::config::CConfigFileBase& cfg, const std::string& section, const std::string& key)
{
	const std::string s = readString(cfg, section, key);
	errno = 0;
	char* end = nullptr;
	const long v = std::strtol(s.c_str(), &end, 10);
	if (s.empty() || errno != 0 || end != s.c_str() + s.size())
		fail(cfg, section, key, "'" + s + "' is not an integer");
	return v;
}

long readInt(
	const mrpt::config::CConfigFileBase& cfg, const std::string& section, const std::string& key,
	long fallback)
{
	return hasKey(cfg, section, key) ? readInt(cfg, section, key) : fallback;
}

bool readBool(
	const mrpt::config::CConfigFileBase& cfg, const std::string& section, const std::string& key,
	bool fallback)
{
	if (!hasKey(cfg, section, key)) return fallback;
	std::string s = readString(cfg, section, key);
	std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::tolower(c); });
	if (s == "true" || s == "yes" || s == "on" || s == "1") return true;
	if (s == "false" || s == "no" || s == "off" || s == "0") return false;
	fail(cfg, section, key, "'" + s + "' is not a boolean (true/false)");
}

std::vector<std::string> splitFields(const std::string& text)
{
	std::string t = text;
	std::replace(t.begin(), t.end(), ',', ' ');
	std::istringstream is(t);
	std::vector<std::string> out;
	for (std::string f; is >> f;) out.push_back(f);
	return out;
}

std::vector<double> readDoubles(
	const mrpt::config::CConfigFileBase& cfg, const std::string& section, const std::string& key,
	size_t expected_count)
{
	const std::string s = readString(cfg, section, key);
	std::vector<double> out;
	for (const auto& f : splitFields(s))
	{
		double v = 0;
		if (!parseDouble(f, v)) fail(cfg, section, key, "'" + f + "' in '" + s + "' is not a number");
		out.push_back(v);
	}
	if (expected_count != 0 && out.size() != expected_count)
		fail(
			cfg, section, key,
			"expected " + std::to_string(expected_count) + " numbers, got " +
				std::to_string(out.size()) + " in '" + s + "'");
	return out;
}

void requireInRange(
	const mrpt::config::CConfigFileBase& cfg, const std::string& section, const std::string& key,
	double value, double lo, double hi)
{
	if (value < lo || value > hi)
	{
		std::ostringstream os;
		os << "value " << value << " outside the allowed range [" << lo << ", " << hi << "]";
		fail(cfg, section, key, os.str());
	}
}

double readDoubleInRange(
	const mrpt::config::CConfigFileBase& cfg, const std::string& section, const std::string& key,
	double lo, double hi)
{
	const double v = readDouble(cfg, section, key);
	requireInRange(cfg, section, key, v, lo, hi);
	return v;
}

}  // namespace mrolr::util
