#include "SlamSetup.h"

#include <mrolr/util/Config.h>

#include <mrpt/config/CConfigFile.h>

#include <filesystem>
#include <fstream>

namespace mrolr::apps
{
namespace
{
mrpt::config::CConfigFile openConfig(const std::string& path)
{
	if (!std::ifstream(path).good())
		throw util::ConfigError(path + ": cannot open the configuration file");
	return mrpt::config::CConfigFile(path);
}
}  // namespace

SlamSetup loadSetup(const std::string& config_path)
{
	SlamSetup s;
	const auto cfg = openConfig(config_path);
	s.run.loadFromConfigFile(cfg, "slam_run");
	s.vision.loadFromConfigFile(cfg, "vision");
	s.slam.loadFromConfigFile(cfg, "slam");
	const auto dir = std::filesystem::path(config_path).parent_path();
	const auto bisight = openConfig((dir / s.run.bisight_config_file).string());
	s.bisight.loadFromConfigFile(bisight, "bisight");
	s.slam.head.loadFromConfigFile(bisight, "bisight");
	const auto labmate = openConfig((dir / s.run.labmate_config_file).string());
	s.labmate.loadFromConfigFile(labmate, "labmate");
	s.trajectory.loadFromConfigFile(labmate, "trajectory");
	return s;
}

}  // namespace mrolr::apps
