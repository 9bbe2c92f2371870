#pragma once
// Loading one section of an .ini file into an options struct, with the file's absence reported as a
// util::ConfigError naming the path (internal to the arm area).

#include <mrolr/util/Config.h>

#include <mrpt/config/CConfigFile.h>

#include <fstream>
#include <string>

namespace mrolr::arm::detail
{
template <class Options>
Options loadSection(const std::string& path, const std::string& section, const std::string& what)
{
	if (!std::ifstream(path).good()) throw util::ConfigError(path + ": cannot open the " + what);
	mrpt::config::CConfigFile cfg(path);
	Options o;
	o.loadFromConfigFile(cfg, section);
	return o;
}

}  // namespace mrolr::arm::detail
