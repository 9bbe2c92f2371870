#include "SlamSetup.h"

#include <mrolr/util/Config.h>

#include <mrpt/config/CConfigFile.h>

#include <filesystem>
#include <fstream>

namespace mrolr::apps
{
SlamSetup loadSetup(const std::string& config_path)
{
	SlamSetup s;
	const auto cfg = util::openConfigFile(config_path);
	s.run.loadFromConfigFile(cfg, "slam_run");
	s.vision.loadFromConfigFile(cfg, "vision");
	s.slam.loadFromConfigFile(cfg, "slam");
	const auto dir = std::filesystem::path(config_path).parent_path();
	const auto bisight = util::openConfigFile((dir / s.run.bisight_config_file).string(), "bisight_config_file");
	s.bisight.loadFromConfigFile(bisight, "bisight");
	s.slam.head.loadFromConfigFile(bisight, "bisight");
	const auto labmate = util::openConfigFile((dir / s.run.labmate_config_file).string(), "labmate_config_file");
	s.labmate.loadFromConfigFile(labmate, "labmate");
	s.trajectory.loadFromConfigFile(labmate, "trajectory");
	return s;
}

}  // namespace mrolr::apps
