// A configuration file with its base files laid under it (ConfigFile.h).
#include <mrolr/util/Config.h>
#include <mrolr/util/ConfigFile.h>

#include <mrpt/config/CConfigFile.h>

#include <filesystem>
#include <fstream>
#include <memory>
#include <set>

namespace mrolr::util
{
namespace
{
/** Longest chain of bases: deeper means a file names itself through others. */
constexpr size_t kMaxBaseDepth = 8;

/** One file of the chain, read once. */
struct Link
{
	std::string path;
	std::unique_ptr<mrpt::config::CConfigFile> file;
};

/** Every file of the chain, the opened one first. */
std::vector<Link> chainOf(const std::string& path, const std::string& named_by)
{
	std::vector<Link> chain;
	std::set<std::string> seen;  // canonical paths
	std::string next = path, by = named_by;
	while (!next.empty())
	{
		if (!std::ifstream(next).good())
			throw ConfigError("cannot open '" + next + "'" +
			                  (by.empty() ? std::string() : " (named by " + by + ")"));
		if (!seen.insert(std::filesystem::weakly_canonical(next).string()).second)
			throw ConfigError(by + ": the bases loop back to '" + next + "'");
		if (chain.size() == kMaxBaseDepth)
			throw ConfigError("'" + path + "': more than " + std::to_string(kMaxBaseDepth) +
			                  " base files");
		chain.push_back({next, std::make_unique<mrpt::config::CConfigFile>(next)});
		const auto& cfg = *chain.back().file;
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
	const auto chain = chainOf(path, named_by);
	for (const auto& link : chain) out.chain_.push_back(link.path);
	for (auto it = chain.rbegin(); it != chain.rend(); ++it)  // the deepest base first
	{
		std::vector<std::string> sections;
		it->file->getAllSections(sections);
		for (const auto& section : sections)
		{
			if (section == "base") continue;
			std::vector<std::string> keys;
			it->file->getAllKeys(section, keys);
			for (const auto& key : keys)
			{
				out.write(section, key, it->file->read_string(section, key, ""));
				out.origin_[{section, key}] = it->path;
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
