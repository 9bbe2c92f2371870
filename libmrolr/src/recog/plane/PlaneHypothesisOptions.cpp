// [plane_hypotheses]: its keys declared once (util/OptionsBinder.h).
#include <mrolr/recog/plane/PlaneHypotheses.h>
#include <mrolr/util/OptionsBinder.h>

namespace mrolr::recog
{
namespace
{
using P = PlaneHypothesisOptions;
using util::Presence;

const util::OptionsBinder<P>& binder()
{
	static const auto b =
	    util::OptionsBinder<P>()
	        .flag("enable", &P::enable)
	        .choice("run_when", &P::run_when,
	                util::ChoiceNames<PlaneRunWhen>{{"always", PlaneRunWhen::Always},
	                                                {"not_found", PlaneRunWhen::NotFound}}, util::Presence::Optional)
	        .number("rim_normal_tol_deg", &P::rim_normal_tol_deg, 0, 90, util::Presence::Optional)
	        .number("scene_normal_tol_deg", &P::scene_normal_tol_deg, 0, 90, util::Presence::Optional)
	        .number("radius_tol_mm", &P::radius_tol_mm, 0, 1000, util::Presence::Optional)
	        .number("height_tol_mm", &P::height_tol_mm, 0, 1000, util::Presence::Optional)
	        .number("horizontal_tol_deg", &P::horizontal_tol_deg, 0, 90, util::Presence::Optional)
	        .number("max_length_ratio", &P::max_length_ratio, 0.01, 100, util::Presence::Optional)
	        .number("min_line_mm", &P::min_line_mm, 0, 1e4, util::Presence::Optional)
	        .number("rim_yaw_step_deg", &P::rim_yaw_step_deg, 1, 360, util::Presence::Optional)
	        .integer("max_hypotheses", &P::max_hypotheses, 1, 100000, util::Presence::Optional)
	        .number("prerank_spacing_mm", &P::prerank_spacing_mm, 0.5, 1000, util::Presence::Optional)
	        .number("min_image_score", &P::min_image_score, 0, 1, util::Presence::Optional)
	        .number("max_base_offset_mm", &P::max_base_offset_mm, 0, 1000, util::Presence::Optional)
	        // the limb and edge-pair sources of hypotheses are stages a user may leave out
	        .flag("limb_hypotheses", &P::limb_hypotheses, Presence::Optional)
	        .number("limb_vertical_tol_deg", &P::limb_vertical_tol_deg, 0, 90, Presence::Optional)
	        .number("limb_max_taper_mm", &P::limb_max_taper_mm, 0, 1000, Presence::Optional)
	        .number("limb_min_mm", &P::limb_min_mm, 0, 1e4, Presence::Optional)
	        .flag("edge_pair_hypotheses", &P::edge_pair_hypotheses, Presence::Optional)
	        .number("edge_pair_min_mm", &P::edge_pair_min_mm, 0, 1e4, Presence::Optional)
	        .number("edge_pair_width_tol_mm", &P::edge_pair_width_tol_mm, 0, 1000,
	                Presence::Optional)
	        .number("edge_pair_min_image_score", &P::edge_pair_min_image_score, 0, 1,
	                Presence::Optional);
	return b;
}
}  // namespace

void PlaneHypothesisOptions::loadFromConfigFile(const mrpt::config::CConfigFileBase& cfg,
                                                const std::string& section)
{
	// the whole section is optional (callers without a support plane never use it)
	if (cfg.sectionExists(section)) binder().load(cfg, section, *this);
}

void PlaneHypothesisOptions::dump(std::ostream& out) const
{
	binder().dump(out, *this);
}

}  // namespace mrolr::recog
