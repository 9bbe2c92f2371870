#include <mrolr/recog/ImageVerifier.h>
#include <mrolr/util/Config.h>

namespace mrolr::recog
{
using util::readDoubleInRange;

namespace
{
int readIntInRange(const mrpt::config::CConfigFileBase& cfg, const std::string& section,
                   const std::string& key, int lo, int hi)
{
	const long v = util::readInt(cfg, section, key);
	util::requireInRange(cfg, section, key, static_cast<double>(v), lo, hi);
	return static_cast<int>(v);
}
}  // namespace

void ImageVerificationOptions::loadFromConfigFile(const mrpt::config::CConfigFileBase& cfg,
                                                  const std::string& section)
{
	blur_sigma_px = readDoubleInRange(cfg, section, "blur_sigma_px", 0, 20);
	canny_low = readDoubleInRange(cfg, section, "canny_low", 0, 10000);
	canny_high = readDoubleInRange(cfg, section, "canny_high", canny_low, 10000);
	edge_distance_px = readDoubleInRange(cfg, section, "edge_distance_px", 0, 100);
	orientation_tol_deg = readDoubleInRange(cfg, section, "orientation_tol_deg", 0, 90);
	sample_spacing_mm = readDoubleInRange(cfg, section, "sample_spacing_mm", 0.1, 1000);
	min_samples = readIntInRange(cfg, section, "min_samples", 1, 1000000);
	min_score = readDoubleInRange(cfg, section, "min_score", 0, 1);
	prefilter_score = readDoubleInRange(cfg, section, "prefilter_score", 0, 1);
	refine_candidates = readIntInRange(cfg, section, "refine_candidates", 0, 1000);
	yaw_step_deg = readDoubleInRange(cfg, section, "yaw_step_deg", 0, 180);
	truncate_px = readDoubleInRange(cfg, section, "truncate_px", 0.1, 1000);
	util::readString(cfg, section, "limbs");  // required: throws naming the key when missing
	limbs = util::readBool(cfg, section, "limbs", true);
	util::readString(cfg, section, "revolution_visibility");
	revolution_visibility = util::readBool(cfg, section, "revolution_visibility", true);
	occluder_margin_mm = util::readDouble(cfg, section, "occluder_margin_mm", occluder_margin_mm);
	util::requireInRange(cfg, section, "occluder_margin_mm", occluder_margin_mm, 0, 1000);
	min_unoccluded_fraction =
	    util::readDouble(cfg, section, "min_unoccluded_fraction", min_unoccluded_fraction);
	util::requireInRange(cfg, section, "min_unoccluded_fraction", min_unoccluded_fraction, 0, 1);
	mutual_occlusion = util::readBool(cfg, section, "mutual_occlusion", mutual_occlusion);
	min_in_image_fraction =
	    util::readDouble(cfg, section, "min_in_image_fraction", min_in_image_fraction);
	util::requireInRange(cfg, section, "min_in_image_fraction", min_in_image_fraction, 0, 1);
}

void ImageVerificationOptions::dump(std::ostream& out) const
{
	out << "blur_sigma_px = " << blur_sigma_px << "\ncanny_low = " << canny_low
	    << "\ncanny_high = " << canny_high << "\nedge_distance_px = " << edge_distance_px
	    << "\norientation_tol_deg = " << orientation_tol_deg
	    << "\nsample_spacing_mm = " << sample_spacing_mm << "\nmin_samples = " << min_samples
	    << "\nmin_score = " << min_score << "\nprefilter_score = " << prefilter_score
	    << "\nrefine_candidates = " << refine_candidates << "\nyaw_step_deg = " << yaw_step_deg
	    << "\ntruncate_px = " << truncate_px << "\nlimbs = " << (limbs ? "true" : "false")
	    << "\nrevolution_visibility = " << (revolution_visibility ? "true" : "false")
	    << "\noccluder_margin_mm = " << occluder_margin_mm
	    << "\nmin_unoccluded_fraction = " << min_unoccluded_fraction
	    << "\nmutual_occlusion = " << (mutual_occlusion ? "true" : "false")
	    << "\nmin_in_image_fraction = " << min_in_image_fraction << "\n";
}

}  // namespace mrolr::recog
