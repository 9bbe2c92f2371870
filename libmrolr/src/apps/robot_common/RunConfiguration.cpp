// The run's effective configuration kept with its outputs (RunConfiguration.h).
#include <mrolr/apps/RunConfiguration.h>

#include <mrolr/util/Config.h>

#include <mrpt/config/CConfigFileMemory.h>

#include <ctime>
#include <filesystem>
#include <iomanip>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace mrolr::apps
{
std::string utcStamp()
{
	const std::time_t now = std::time(nullptr);
	std::tm tm{};
	gmtime_r(&now, &tm);
	std::ostringstream s;
	s << std::put_time(&tm, "%Y%m%d-%H%M%S");
	return s.str();
}

namespace fs = std::filesystem;

namespace
{
void copyInto(const fs::path& from, const fs::path& to)
{
	std::error_code ec;
	fs::copy_file(from, to, fs::copy_options::overwrite_existing, ec);
	if (ec)
		throw std::runtime_error("cannot copy '" + from.string() + "' to '" + to.string() +
		                         "': " + ec.message());
}

bool endsWith(const std::string& s, const std::string& tail)
{
	return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

/** Every `*_file` of [files] copied into @p run (key = its copy's name), models_dir's files into
 * run/models. */
void copyNamedFiles(mrpt::config::CConfigFileMemory& cfg, const fs::path& base, const fs::path& run)
{
	auto resolved = [&](const std::string& p)
	{
		const fs::path q(p);
		return (q.is_absolute() ? q : base / q).lexically_normal();
	};
	std::vector<std::string> keys;
	cfg.getAllKeys("files", keys);
	for (const auto& key : keys)
	{
		const std::string value = cfg.read_string("files", key, "");
		if (endsWith(key, "_file"))
		{
			const fs::path from = resolved(value);
			copyInto(from, run / from.filename());
			cfg.write("files", key, from.filename().string());
		}
		else if (key == "models_dir")
		{
			fs::create_directories(run / "models");
			for (const auto& e : fs::directory_iterator(resolved(value)))
				if (e.is_regular_file()) copyInto(e.path(), run / "models" / e.path().filename());
			cfg.write("files", key, "models");
		}
	}
}
}  // namespace

std::string writeRunConfiguration(const RunInputs& in, const mission::MissionOptions& o,
                                  const std::string& out_dir)
{
	const fs::path run = fs::path(out_dir) / "run";
	fs::create_directories(run);
	// the file with its bases laid under it: run/mission.ini stands alone
	mrpt::config::CConfigFileMemory cfg(util::openConfigFile(in.config_path).getContent());
	for (const auto& [section, key, value] : in.sets) cfg.write(section, key, value);
	const fs::path base = fs::path(in.config_path).parent_path();
	copyNamedFiles(cfg, base, run);
	fs::create_directories(run / "plan");
	o.plan.save((run / "plan" / "plan.ini").string());
	cfg.write("mission", "plan", "plan/plan.ini");
	const std::string world = in.world_path.empty()
	                              ? cfg.read_string("simulator", "world_file", "")
	                              : fs::absolute(in.world_path).string();
	if (!world.empty())
	{
		const fs::path w(world);
		cfg.write("simulator", "world_file",
		          (w.is_absolute() ? w : fs::absolute(base / w)).lexically_normal().string());
	}
	const std::string ini = (run / "mission.ini").string();
	std::ofstream f(ini);
	f << "# The mission as it ran (mrolr-mission --config " << ini << " runs it again)\n"
	  << cfg.getContent();
	std::ofstream cmd(run / "command.txt");
	for (const auto& a : in.command) cmd << a << "\n";
	if (!f || !cmd) throw std::runtime_error("cannot write the run's record in '" + run.string() + "'");
	return ini;
}

}  // namespace mrolr::apps
