#pragma once
// The configuration of an mrolr-slam run: config/slam.ini and the base and head files it names.
#include <mrolr/apps/SlamApp.h>

#include <string>

namespace mrolr::apps
{
/** Everything a live run or a replay needs, read from the config files. */
struct SlamSetup
{
	SlamRunOptions run;
	vision::VisionOptions vision;
	slam::SlamOptions slam;
	base::LabmateOptions labmate;
	base::TrajectoryOptions trajectory;
	geometry::BiSightOptions bisight;
};

/** Reads @p config_path ([slam_run], [vision], [slam]) and the bisight/labmate files it names
 * (relative to its folder). Errors name file, section and key. */
SlamSetup loadSetup(const std::string& config_path);

}  // namespace mrolr::apps
