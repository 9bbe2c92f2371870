// Section [obstacle] of the mission file (thesis 5.8.1.2).
#include <mrolr/mission/ObstacleOptions.h>
#include <mrolr/util/Config.h>

#include <ostream>

namespace mrolr::mission
{
using mrpt::config::CConfigFileBase;

namespace
{
void readGaze(const CConfigFileBase& c, const std::string& s, ObstacleOptions& o)
{
	using util::readDouble;
	o.tilt_deg = readDouble(c, s, "tilt_deg");
	o.fixation_distance_m = readDouble(c, s, "fixation_distance_m");
	o.side_pan_deg = readDouble(c, s, "side_pan_deg");
	o.look_time_s = readDouble(c, s, "look_time_s");
	util::requireInRange(c, s, "tilt_deg", o.tilt_deg, -80, 0);
	util::requireInRange(c, s, "fixation_distance_m", o.fixation_distance_m, 0.3, 10);
	util::requireInRange(c, s, "side_pan_deg", o.side_pan_deg, 0, 90);
	util::requireInRange(c, s, "look_time_s", o.look_time_s, 0, 60);
}

void readRobot(const CConfigFileBase& c, const std::string& s, ObstacleOptions& o)
{
	using util::readDouble;
	o.range_m = readDouble(c, s, "range_m");
	o.corridor_half_width_m = readDouble(c, s, "corridor_half_width_m");
	o.clearance_m = readDouble(c, s, "clearance_m");
	o.assumed_depth_m = readDouble(c, s, "assumed_depth_m");
	o.table_margin_m = readDouble(c, s, "table_margin_m");
	o.max_detours_per_leg = static_cast<int>(util::readInt(c, s, "max_detours_per_leg"));
	util::requireInRange(c, s, "range_m", o.range_m, 0.1, 5);
	util::requireInRange(c, s, "corridor_half_width_m", o.corridor_half_width_m, 0.05, 2);
	util::requireInRange(c, s, "clearance_m", o.clearance_m, 0, 2);
	util::requireInRange(c, s, "assumed_depth_m", o.assumed_depth_m, 0, 5);
	util::requireInRange(c, s, "table_margin_m", o.table_margin_m, 0, 2);
	util::requireInRange(c, s, "max_detours_per_leg", o.max_detours_per_leg, 0, 20);
}

void readMatcher(const CConfigFileBase& c, const std::string& s, ObstacleOptions& o)
{
	using util::readDouble;
	o.min_height_m = readDouble(c, s, "min_height_m");
	o.max_height_m = readDouble(c, s, "max_height_m");
	o.min_points = static_cast<int>(util::readInt(c, s, "min_points"));
	o.min_bin_points = static_cast<int>(util::readInt(c, s, "min_bin_points"));
	o.image_scale = readDouble(c, s, "image_scale");
	o.min_depth_m = readDouble(c, s, "min_depth_m");
	o.max_depth_m = readDouble(c, s, "max_depth_m");
	o.block_size_px = static_cast<int>(util::readInt(c, s, "block_size_px"));
	o.min_texture_grey = readDouble(c, s, "min_texture_grey");
	o.max_disparity_gradient = readDouble(c, s, "max_disparity_gradient");
	util::requireInRange(c, s, "min_height_m", o.min_height_m, 0, 2);
	util::requireInRange(c, s, "max_height_m", o.max_height_m, o.min_height_m, 5);
	util::requireInRange(c, s, "min_points", o.min_points, 1, 1e6);
	util::requireInRange(c, s, "min_bin_points", o.min_bin_points, 1, 1e6);
	util::requireInRange(c, s, "image_scale", o.image_scale, 0.1, 1);
	util::requireInRange(c, s, "min_depth_m", o.min_depth_m, 0.05, 10);
	util::requireInRange(c, s, "max_depth_m", o.max_depth_m, o.min_depth_m + 0.01, 50);
	util::requireInRange(c, s, "block_size_px", o.block_size_px, 1, 21);
	util::requireInRange(c, s, "min_texture_grey", o.min_texture_grey, 0, 128);
	util::requireInRange(c, s, "max_disparity_gradient", o.max_disparity_gradient, 0.01, 1e3);
	if (o.block_size_px % 2 == 0)
		throw util::ConfigError(util::describeKey(c, s, "block_size_px") + ": must be odd, got " +
		                        std::to_string(o.block_size_px));
}
}  // namespace

void ObstacleOptions::loadFromConfigFile(const CConfigFileBase& cfg, const std::string& section)
{
	readGaze(cfg, section, *this);
	readRobot(cfg, section, *this);
	readMatcher(cfg, section, *this);
}

void ObstacleOptions::dump(std::ostream& out) const
{
	out << "tilt_deg = " << tilt_deg << "\nfixation_distance_m = " << fixation_distance_m
	    << "\nside_pan_deg = " << side_pan_deg << "\nlook_time_s = " << look_time_s
	    << "\nrange_m = " << range_m << "\ncorridor_half_width_m = " << corridor_half_width_m
	    << "\nclearance_m = " << clearance_m << "\nassumed_depth_m = " << assumed_depth_m
	    << "\ntable_margin_m = " << table_margin_m
	    << "\nmax_detours_per_leg = " << max_detours_per_leg << "\nmin_height_m = " << min_height_m
	    << "\nmax_height_m = " << max_height_m << "\nmin_points = " << min_points
	    << "\nmin_bin_points = " << min_bin_points << "\nimage_scale = " << image_scale
	    << "\nmin_depth_m = " << min_depth_m << "\nmax_depth_m = " << max_depth_m
	    << "\nblock_size_px = " << block_size_px << "\nmin_texture_grey = " << min_texture_grey
	    << "\nmax_disparity_gradient = " << max_disparity_gradient << "\n";
}

}  // namespace mrolr::mission
