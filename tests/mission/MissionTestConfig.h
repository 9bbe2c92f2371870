#pragma once
// The default mission file in memory, for tests that override keys.
#include <mrolr/mission/MissionOptions.h>

#include <mrpt/config/CConfigFileMemory.h>

#include <fstream>
#include <sstream>
#include <string>

namespace mrolr::mission::test
{
inline std::string configDir()
{
	return std::string(MROLR_SOURCE_DIR) + "/config";
}

/** A mission file of config/ in memory (keys can be overridden without touching the file). */
inline mrpt::config::CConfigFileMemory missionConfig(const std::string& file)
{
	std::ifstream f(configDir() + "/" + file);
	std::stringstream s;
	s << f.rdbuf();
	return mrpt::config::CConfigFileMemory(s.str());
}

inline mrpt::config::CConfigFileMemory defaultMissionConfig()
{
	return missionConfig("mission_sim.ini");
}

inline MissionOptions optionsFrom(const mrpt::config::CConfigFileBase& cfg)
{
	return MissionOptions::fromConfig(cfg, configDir());
}

}  // namespace mrolr::mission::test
