// Options of the horizontal circles (HorizontalCircles.h): the horizontal_circle* keys of [scene].
#include <mrolr/stereo/HorizontalCircles.h>
#include <mrolr/util/OptionsBinder.h>

#include <ostream>

namespace mrolr::stereo
{
namespace
{
using O = HorizontalCircleOptions;
constexpr auto kOpt = util::Presence::Optional;  // [scene]: docs/config.md

const util::OptionsBinder<O>& horizontalCircleOptionsBinder()
{
	static const auto b = util::OptionsBinder<O>()
	    .flag("horizontal_circles", &O::enabled, kOpt)
	    .number("horizontal_circle_max_residual_px", &O::max_residual_px, 0.05, 20, kOpt)
	    .number("horizontal_circle_max_axis_ratio", &O::max_axis_ratio, 1, 10, kOpt)
	    .integer("horizontal_circle_min_depth_matches", &O::min_depth_matches, 1, 1000000, kOpt)
	    .number("horizontal_circle_min_radius_mm", &O::min_radius_mm, 0, 1e4, kOpt)
	    .number("horizontal_circle_max_radius_mm", &O::max_radius_mm, 0, 1e5, kOpt)
	    .number("horizontal_circle_min_arc_deg", &O::min_arc_deg, 0, 360, kOpt)
	    .number("horizontal_circle_min_run_arc_deg", &O::min_run_arc_deg, 0, 360, kOpt)
	    .number("horizontal_circle_max_chord_turn_deg", &O::max_chord_turn_deg, 0, 90, kOpt)
	    .flag("horizontal_circle_right_extremes", &O::right_extremes, kOpt);
	return b;
}
}  // namespace

void HorizontalCircleOptions::loadFromConfigFile(const mrpt::config::CConfigFileBase& cfg,
                                                const std::string& section)
{
	horizontalCircleOptionsBinder().load(cfg, section, *this);
	util::requireInRange(cfg, section, "horizontal_circle_max_radius_mm", max_radius_mm,
	                     min_radius_mm, 1e5);
}

void HorizontalCircleOptions::dump(std::ostream& out) const
{
	horizontalCircleOptionsBinder().dump(out, *this);
}

}  // namespace mrolr::stereo
