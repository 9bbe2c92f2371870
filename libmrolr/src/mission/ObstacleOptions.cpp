// Section [obstacle] of the mission file (thesis 5.8.1.2).
#include <mrolr/mission/ObstacleOptions.h>
#include <mrolr/util/OptionsBinder.h>

#include <ostream>

namespace mrolr::mission
{
using mrpt::config::CConfigFileBase;

namespace
{
using O = ObstacleOptions;

const util::OptionsBinder<O>& binder()
{
	static const auto b =
	    util::OptionsBinder<O>()
	        // the looks (thesis 5.8.1.2)
	        .number("tilt_deg", &O::tilt_deg, -80, 0)
	        .number("fixation_distance_m", &O::fixation_distance_m, 0.3, 10)
	        .number("side_pan_deg", &O::side_pan_deg, 0, 90)
	        .number("look_time_s", &O::look_time_s, 0, 60)
	        // the robot's corridor and the detours
	        .number("range_m", &O::range_m, 0.1, 5)
	        .number("corridor_half_width_m", &O::corridor_half_width_m, 0.05, 2)
	        .number("clearance_m", &O::clearance_m, 0, 2)
	        .number("assumed_depth_m", &O::assumed_depth_m, 0, 5)
	        .number("table_margin_m", &O::table_margin_m, 0, 2)
	        .integer("max_detours_per_leg", &O::max_detours_per_leg, 0, 20)
	        // the block matcher and the floor's obstacles
	        .number("min_height_m", &O::min_height_m, 0, 2)
	        .number("max_height_m", &O::max_height_m, 0, 5)
	        .integer("min_points", &O::min_points, 1, 1000000)
	        .integer("min_bin_points", &O::min_bin_points, 1, 1000000)
	        .number("image_scale", &O::image_scale, 0.1, 1)
	        .number("min_depth_m", &O::min_depth_m, 0.05, 10)
	        .number("max_depth_m", &O::max_depth_m, 0.06, 50)
	        .integer("block_size_px", &O::block_size_px, 1, 21)
	        .number("min_texture_grey", &O::min_texture_grey, 0, 128)
	        .number("max_disparity_gradient", &O::max_disparity_gradient, 0.01, 1e3);
	return b;
}
}  // namespace

void ObstacleOptions::loadFromConfigFile(const CConfigFileBase& cfg, const std::string& section)
{
	binder().load(cfg, section, *this);
	util::requireInRange(cfg, section, "max_height_m", max_height_m, min_height_m, 5);
	util::requireInRange(cfg, section, "max_depth_m", max_depth_m, min_depth_m + 0.01, 50);
	if (block_size_px % 2 == 0)
		throw util::ConfigError(util::describeKey(cfg, section, "block_size_px") +
		                        ": must be odd, got " + std::to_string(block_size_px));
}

void ObstacleOptions::dump(std::ostream& out) const
{
	binder().dump(out, *this);
}

}  // namespace mrolr::mission
