// Options of the horizontal circles (HorizontalCircles.h): the horizontal_circle* keys of [scene].
#include <mrolr/stereo/HorizontalCircles.h>
#include <mrolr/util/Config.h>

#include <ostream>

namespace mrolr::stereo
{
void HorizontalCircleOptions::loadFromConfigFile(const mrpt::config::CConfigFileBase& cfg,
                                                 const std::string& section)
{
	auto rd = [&](const char* k, double& v) { v = util::readDouble(cfg, section, k, v); };
	enabled = util::readBool(cfg, section, "horizontal_circles", enabled);
	rd("horizontal_circle_max_residual_px", max_residual_px);
	rd("horizontal_circle_max_axis_ratio", max_axis_ratio);
	min_depth_matches = static_cast<int>(
	    util::readInt(cfg, section, "horizontal_circle_min_depth_matches", min_depth_matches));
	rd("horizontal_circle_min_radius_mm", min_radius_mm);
	rd("horizontal_circle_max_radius_mm", max_radius_mm);
	rd("horizontal_circle_min_arc_deg", min_arc_deg);
	rd("horizontal_circle_min_run_arc_deg", min_run_arc_deg);
	right_extremes =
	    util::readBool(cfg, section, "horizontal_circle_right_extremes", right_extremes);
	rd("horizontal_circle_max_chord_turn_deg", max_chord_turn_deg);
	util::requireInRange(cfg, section, "horizontal_circle_min_run_arc_deg", min_run_arc_deg, 0,
	                     360);
	util::requireInRange(cfg, section, "horizontal_circle_max_chord_turn_deg", max_chord_turn_deg,
	                     0, 90);
	util::requireInRange(cfg, section, "horizontal_circle_max_residual_px", max_residual_px, 0.05,
	                     20);
	util::requireInRange(cfg, section, "horizontal_circle_max_axis_ratio", max_axis_ratio, 1, 10);
	util::requireInRange(cfg, section, "horizontal_circle_min_depth_matches", min_depth_matches, 1,
	                     1e6);
	util::requireInRange(cfg, section, "horizontal_circle_min_radius_mm", min_radius_mm, 0, 1e4);
	util::requireInRange(cfg, section, "horizontal_circle_max_radius_mm", max_radius_mm,
	                     min_radius_mm, 1e5);
	util::requireInRange(cfg, section, "horizontal_circle_min_arc_deg", min_arc_deg, 0, 360);
}

void HorizontalCircleOptions::dump(std::ostream& out) const
{
	out << "horizontal_circles = " << enabled
	    << "\nhorizontal_circle_max_residual_px = " << max_residual_px
	    << "\nhorizontal_circle_max_axis_ratio = " << max_axis_ratio
	    << "\nhorizontal_circle_min_depth_matches = " << min_depth_matches
	    << "\nhorizontal_circle_min_radius_mm = " << min_radius_mm
	    << "\nhorizontal_circle_max_radius_mm = " << max_radius_mm
	    << "\nhorizontal_circle_min_arc_deg = " << min_arc_deg
	    << "\nhorizontal_circle_min_run_arc_deg = " << min_run_arc_deg
	    << "\nhorizontal_circle_max_chord_turn_deg = " << max_chord_turn_deg
	    << "\nhorizontal_circle_right_extremes = " << right_extremes << "\n";
}

}  // namespace mrolr::stereo
