// [image_verification]: its keys declared once (util/OptionsBinder.h).
#include <mrolr/recog/images/ImageVerificationOptions.h>
#include <mrolr/util/OptionsBinder.h>

namespace mrolr::recog
{
namespace
{
using I = ImageVerificationOptions;

const util::OptionsBinder<I>& binder()
{
	static const auto b = util::OptionsBinder<I>()
	                          .number("blur_sigma_px", &I::blur_sigma_px, 0, 20, util::Presence::Optional)
	                          .number("canny_low", &I::canny_low, 0, 10000)
	                          .number("canny_high", &I::canny_high, 0, 10000)
	                          .number("edge_distance_px", &I::edge_distance_px, 0, 100)
	                          .number("orientation_tol_deg", &I::orientation_tol_deg, 0, 90, util::Presence::Optional)
	                          .number("sample_spacing_mm", &I::sample_spacing_mm, 0.1, 1000, util::Presence::Optional)
	                          .integer("min_samples", &I::min_samples, 1, 1000000, util::Presence::Optional)
	                          .number("min_score", &I::min_score, 0, 1)
	                          .number("prefilter_score", &I::prefilter_score, 0, 1, util::Presence::Optional)
	                          .integer("refine_candidates", &I::refine_candidates, 0, 1000, util::Presence::Optional)
	                          .number("yaw_step_deg", &I::yaw_step_deg, 0, 180, util::Presence::Optional)
	                          .number("truncate_px", &I::truncate_px, 0.1, 1000, util::Presence::Optional)
	                          .flag("limbs", &I::limbs, util::Presence::Optional)
	                          .flag("revolution_visibility", &I::revolution_visibility, util::Presence::Optional)
	                          .number("occluder_margin_mm", &I::occluder_margin_mm, 0, 1000, util::Presence::Optional)
	                          .number("min_unoccluded_fraction", &I::min_unoccluded_fraction, 0, 1, util::Presence::Optional)
	                          .flag("mutual_occlusion", &I::mutual_occlusion, util::Presence::Optional)
	                          .number("min_in_image_fraction", &I::min_in_image_fraction, 0, 1, util::Presence::Optional);
	return b;
}
}  // namespace

void ImageVerificationOptions::loadFromConfigFile(const mrpt::config::CConfigFileBase& cfg,
                                                  const std::string& section)
{
	binder().load(cfg, section, *this);
	util::requireInRange(cfg, section, "canny_high", canny_high, canny_low, 10000);
}

void ImageVerificationOptions::dump(std::ostream& out) const
{
	binder().dump(out, *this);
}

}  // namespace mrolr::recog
