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
	        .number("tilt_deg", &O::tilt_deg, -80, 0)
	        .number("range_m", &O::range_m, 0.1, 5)
	        .number("corridor_half_width_m", &O::corridor_half_width_m, 0.05, 2)
	        .fixed({"fixation_distance_m", "side_pan_deg", "look_time_s", "clearance_m",
	                "assumed_depth_m", "table_margin_m", "max_detours_per_leg", "min_height_m",
	                "max_height_m", "min_points", "min_bin_points", "image_scale", "min_depth_m",
	                "max_depth_m", "block_size_px", "min_texture_grey", "max_disparity_gradient"},
	               "mission/ObstacleOptions.h");
	return b;
}
}  // namespace

void ObstacleOptions::loadFromConfigFile(const CConfigFileBase& cfg, const std::string& section)
{
	binder().load(cfg, section, *this);
}

void ObstacleOptions::dump(std::ostream& out) const
{
	binder().dump(out, *this);
}

}  // namespace mrolr::mission
