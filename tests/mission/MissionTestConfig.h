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

inline mrpt::config::CConfigFileMemory defaultMissionConfig()
{
	std::ifstream f(configDir() + "/mission_sim.ini");
	std::stringstream s;
	s << f.rdbuf();
	return mrpt::config::CConfigFileMemory(s.str());
}

inline MissionOptions optionsFrom(const mrpt::config::CConfigFileBase& cfg)
{
	return MissionOptions::fromConfig(cfg, configDir());
}

}  // namespace mrolr::mission::test
