// A configuration file with its base files laid under it (ConfigFile.h).
#include <mrolr/util/Config.h>
#include <mrolr/util/ConfigFile.h>

#include <mrpt/config/CConfigFile.h>

#include <algorithm>
#include <filesystem>
#include <fstream>

namespace mrolr::util
{
namespace
{
/** Longest chain of bases: deeper means a file names itself through others. */
constexpr size_t kMaxBaseDepth = 8;

/** Every file of the chain, the opened one first. */
std::vector<std::string> chainOf(const std::string& path, const std::string& named_by)
{
	std::vector<std::string> chain;
	std::string next = path, by = named_by;
	while (!next.empty())
	{
		if (!std::ifstream(next).good())
			throw ConfigError("cannot open '" + next + "'" +
			                  (by.empty() ? std::string() : " (named by " + by + ")"));
		const auto canonical = std::filesystem::weakly_canonical(next).string();
		for (const auto& seen : chain)
			if (std::filesystem::weakly_canonical(seen).string() == canonical)
				throw ConfigError(
				    describeKey(mrpt::config::CConfigFile(chain.back()), "base", "file") +
				    ": the bases loop back to '" + next + "'");
		if (chain.size() == kMaxBaseDepth)
			throw ConfigError("'" + path + "': more than " + std::to_string(kMaxBaseDepth) +
			                  " base files");
		chain.push_back(next);
		const mrpt::config::CConfigFile cfg(next);
		if (!hasKey(cfg, "base", "file")) break;
		const std::string base = readString(cfg, "base", "file");
		if (base.empty()) throw ConfigError(describeKey(cfg, "base", "file") + ": empty");
		const std::filesystem::path p(base);
		next = (p.is_absolute() ? p : std::filesystem::path(next).parent_path() / p)
		           .lexically_normal()
		           .string();
		by = describeKey(cfg, "base", "file");
	}
	return chain;
}
}  // namespace

ConfigFile ConfigFile::load(const std::string& path, const std::string& named_by)
{
	ConfigFile out;
	out.path_ = path;
	out.chain_ = chainOf(path, named_by);
	for (auto it = out.chain_.rbegin(); it != out.chain_.rend(); ++it)  // the deepest base first
	{
		const mrpt::config::CConfigFile file(*it);
		std::vector<std::string> sections;
		file.getAllSections(sections);
		for (const auto& section : sections)
		{
			if (section == "base") continue;
			std::vector<std::string> keys;
			file.getAllKeys(section, keys);
			for (const auto& key : keys)
			{
				out.write(section, key, file.read_string(section, key, ""));
				out.origin_[{section, key}] = *it;
			}
		}
	}
	return out;
}

void ConfigFile::set(const std::string& section, const std::string& key, const std::string& value,
                     const std::string& origin)
{
	write(section, key, value);
	origin_[{section, key}] = origin;
}

const std::string& ConfigFile::fileOf(const std::string& section, const std::string& key) const
{
	const auto it = origin_.find({section, key});
	return it == origin_.end() ? path_ : it->second;
}

}  // namespace mrolr::util
