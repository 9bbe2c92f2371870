#include <mrolr/recog/PlaneHypotheses.h>
#include <mrolr/util/Config.h>

namespace mrolr::recog
{
void PlaneHypothesisOptions::loadFromConfigFile(const mrpt::config::CConfigFileBase& cfg,
                                                const std::string& section)
{
	// the whole section is optional (callers without a support plane never use it); when it is
	// there, every key must be
	if (!cfg.sectionExists(section)) return;
	if (!util::hasKey(cfg, section, "enable"))
		throw util::ConfigError(util::describeKey(cfg, section, "enable") + ": missing");
	enable = util::readBool(cfg, section, "enable", true);
	run_when = util::readString(cfg, section, "run_when");
	if (run_when != "not_found" && run_when != "always")
		throw util::ConfigError(util::describeKey(cfg, section, "run_when") + ": '" + run_when +
		                        "' is not one of not_found, always");
	auto in = [&](const char* key, double lo, double hi)
	{ return util::readDoubleInRange(cfg, section, key, lo, hi); };
	rim_normal_tol_deg = in("rim_normal_tol_deg", 0, 90);
	scene_normal_tol_deg = in("scene_normal_tol_deg", 0, 90);
	radius_tol_mm = in("radius_tol_mm", 0, 1000);
	height_tol_mm = in("height_tol_mm", 0, 1000);
	horizontal_tol_deg = in("horizontal_tol_deg", 0, 90);
	max_length_ratio = in("max_length_ratio", 0.01, 100);
	min_line_mm = in("min_line_mm", 0, 1e4);
	rim_yaw_step_deg = in("rim_yaw_step_deg", 1, 360);
	const long n = util::readInt(cfg, section, "max_hypotheses");
	util::requireInRange(cfg, section, "max_hypotheses", static_cast<double>(n), 1, 100000);
	max_hypotheses = static_cast<int>(n);
	prerank_spacing_mm = in("prerank_spacing_mm", 0.5, 1000);
	min_image_score = in("min_image_score", 0, 1);
	max_base_offset_mm = in("max_base_offset_mm", 0, 1000);
	// optional: added after the section was first shipped
	if (util::hasKey(cfg, section, "limb_hypotheses"))
		limb_hypotheses = util::readBool(cfg, section, "limb_hypotheses", limb_hypotheses);
	auto optIn = [&](const char* key, double& v, double lo, double hi)
	{
		if (util::hasKey(cfg, section, key)) v = in(key, lo, hi);
	};
	optIn("limb_vertical_tol_deg", limb_vertical_tol_deg, 0, 90);
	optIn("limb_max_taper_mm", limb_max_taper_mm, 0, 1000);
	optIn("limb_min_mm", limb_min_mm, 0, 1e4);
	if (util::hasKey(cfg, section, "edge_pair_hypotheses"))
		edge_pair_hypotheses =
		    util::readBool(cfg, section, "edge_pair_hypotheses", edge_pair_hypotheses);
	optIn("edge_pair_min_mm", edge_pair_min_mm, 0, 1e4);
	optIn("edge_pair_width_tol_mm", edge_pair_width_tol_mm, 0, 1000);
	optIn("edge_pair_min_image_score", edge_pair_min_image_score, 0, 1);
}

void PlaneHypothesisOptions::dump(std::ostream& out) const
{
	out << "enable = " << (enable ? "true" : "false") << "\nrun_when = " << run_when
	    << "\nrim_normal_tol_deg = " << rim_normal_tol_deg
	    << "\nscene_normal_tol_deg = " << scene_normal_tol_deg
	    << "\nradius_tol_mm = " << radius_tol_mm << "\nheight_tol_mm = " << height_tol_mm
	    << "\nhorizontal_tol_deg = " << horizontal_tol_deg
	    << "\nmax_length_ratio = " << max_length_ratio << "\nmin_line_mm = " << min_line_mm
	    << "\nrim_yaw_step_deg = " << rim_yaw_step_deg << "\nmax_hypotheses = " << max_hypotheses
	    << "\nprerank_spacing_mm = " << prerank_spacing_mm
	    << "\nmin_image_score = " << min_image_score
	    << "\nmax_base_offset_mm = " << max_base_offset_mm
	    << "\nlimb_hypotheses = " << (limb_hypotheses ? "true" : "false")
	    << "\nlimb_vertical_tol_deg = " << limb_vertical_tol_deg
	    << "\nlimb_max_taper_mm = " << limb_max_taper_mm << "\nlimb_min_mm = " << limb_min_mm
	    << "\nedge_pair_hypotheses = " << (edge_pair_hypotheses ? "true" : "false")
	    << "\nedge_pair_min_mm = " << edge_pair_min_mm
	    << "\nedge_pair_width_tol_mm = " << edge_pair_width_tol_mm
	    << "\nedge_pair_min_image_score = " << edge_pair_min_image_score << "\n";
}

}  // namespace mrolr::recog
