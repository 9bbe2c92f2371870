// [vision]: its keys declared once (util/OptionsBinder.h).
#include <mrolr/util/OptionsBinder.h>
#include <mrolr/vision/VisionOptions.h>

#include <iomanip>
#include <ostream>

namespace mrolr::vision
{
namespace
{
using V = VisionOptions;

const util::OptionsBinder<V>& binder()
{
	static const auto b =
	    util::OptionsBinder<V>()
	        .integer("patch_size_px", &V::patch_size_px, 3, 101)
	        .number("nssd_threshold", &V::nssd_threshold, 1e-6, 4)
	        // 0 (absent): no ambiguity test, the thesis's matcher
	        .number("nssd_ambiguity_margin", &V::nssd_ambiguity_margin, 0, 4,
	                util::Presence::Optional)
	        .number("search_n_sigma", &V::search_n_sigma, 0.1, 20)
	        .number("epipolar_band_px", &V::epipolar_band_px, 0, 1000)
	        .number("epipolar_min_depth_m", &V::epipolar_min_depth_m, 1e-3, 1e6)
	        .number("epipolar_max_depth_m", &V::epipolar_max_depth_m, 1e-3, 1e6)
	        .number("min_corner_eigenvalue", &V::min_corner_eigenvalue, 0, 1e6)
	        .number("lockon_radius_px", &V::lockon_radius_px, 0, 1000)
	        .integer("fixation_max_attempts", &V::fixation_max_attempts, 1, 100)
	        .number("fixation_search_radius_px", &V::fixation_search_radius_px, 1, 10000)
	        .number("pixel_sigma_px", &V::pixel_sigma_px, 1e-6, 1000)
	        .number("acquire_pan_deg", &V::acquire_pan_deg, 0, 180)
	        .number("acquire_tilt_deg", &V::acquire_tilt_deg, -90, 90)
	        .integer("acquire_box_px", &V::acquire_box_px, 3, 100000)
	        .integer("known_search_box_px", &V::known_search_box_px, 1, 100000)
	        .choice("selection", &V::selection,
	                util::ChoiceNames<Selection>{{"largest_vs", Selection::LargestVs},
	                                             {"saccade", Selection::Saccade}});
	return b;
}
}  // namespace

void VisionOptions::loadFromConfigFile(const mrpt::config::CConfigFileBase& cfg,
                                       const std::string& section)
{
	binder().load(cfg, section, *this);
	if (patch_size_px % 2 == 0)
		throw util::ConfigError(util::describeKey(cfg, section, "patch_size_px") +
		                        ": must be odd (a centre pixel)");
	util::requireInRange(cfg, section, "epipolar_max_depth_m", epipolar_max_depth_m,
	                     epipolar_min_depth_m, 1e6);
	util::requireInRange(cfg, section, "acquire_box_px", acquire_box_px, patch_size_px, 100000);
}

VisionOptions VisionOptions::fromFile(const std::string& path, const std::string& section)
{
	return util::loadOptionsFile<VisionOptions>(path, section);
}

void VisionOptions::dump(std::ostream& out) const
{
	out << std::setprecision(17);
	binder().dump(out, *this);
}

}  // namespace mrolr::vision
