#include <mrolr/util/Config.h>
#include <mrolr/vision/VisionOptions.h>

#include <mrpt/config/CConfigFile.h>

#include <fstream>
#include <iomanip>
#include <ostream>

namespace mrolr::vision
{
namespace
{
double readIn(const mrpt::config::CConfigFileBase& cfg, const std::string& section,
              const std::string& key, double lo, double hi)
{
	const double v = util::readDouble(cfg, section, key);
	util::requireInRange(cfg, section, key, v, lo, hi);
	return v;
}

int readIntIn(const mrpt::config::CConfigFileBase& cfg, const std::string& section,
              const std::string& key, long lo, long hi)
{
	const long v = util::readInt(cfg, section, key);
	util::requireInRange(cfg, section, key, static_cast<double>(v), lo, hi);
	return static_cast<int>(v);
}
}  // namespace

void VisionOptions::loadFromConfigFile(const mrpt::config::CConfigFileBase& cfg,
                                       const std::string& section)
{
	patch_size_px = readIntIn(cfg, section, "patch_size_px", 3, 101);
	if (patch_size_px % 2 == 0)
		throw util::ConfigError(util::describeKey(cfg, section, "patch_size_px") +
		                        ": must be odd (a centre pixel)");
	nssd_threshold = readIn(cfg, section, "nssd_threshold", 1e-6, 4);
	nssd_ambiguity_margin = util::readDouble(cfg, section, "nssd_ambiguity_margin", 0.0);
	util::requireInRange(cfg, section, "nssd_ambiguity_margin", nssd_ambiguity_margin, 0, 4);
	search_n_sigma = readIn(cfg, section, "search_n_sigma", 0.1, 20);
	epipolar_band_px = readIn(cfg, section, "epipolar_band_px", 0, 1000);
	epipolar_min_depth_m = readIn(cfg, section, "epipolar_min_depth_m", 1e-3, 1e6);
	epipolar_max_depth_m = readIn(cfg, section, "epipolar_max_depth_m", epipolar_min_depth_m, 1e6);
	min_corner_eigenvalue = readIn(cfg, section, "min_corner_eigenvalue", 0, 1e6);
	lockon_radius_px = readIn(cfg, section, "lockon_radius_px", 0, 1000);
	fixation_max_attempts = readIntIn(cfg, section, "fixation_max_attempts", 1, 100);
	fixation_search_radius_px = readIn(cfg, section, "fixation_search_radius_px", 1, 10000);
	pixel_sigma_px = readIn(cfg, section, "pixel_sigma_px", 1e-6, 1000);
	acquire_pan_deg = readIn(cfg, section, "acquire_pan_deg", 0, 180);
	acquire_tilt_deg = readIn(cfg, section, "acquire_tilt_deg", -90, 90);
	acquire_box_px = readIntIn(cfg, section, "acquire_box_px", patch_size_px, 100000);
	known_search_box_px = readIntIn(cfg, section, "known_search_box_px", 1, 100000);
	const std::string sel = util::readString(cfg, section, "selection");
	if (sel != "largest_vs" && sel != "saccade")
		throw util::ConfigError(util::describeKey(cfg, section, "selection") + " = '" + sel +
		                        "': expected largest_vs or saccade");
	selection = sel == "saccade" ? Selection::Saccade : Selection::LargestVs;
}

VisionOptions VisionOptions::fromFile(const std::string& path, const std::string& section)
{
	if (!std::ifstream(path).good())
		throw util::ConfigError(path + ": cannot open the configuration file");
	mrpt::config::CConfigFile cfg(path);
	VisionOptions o;
	o.loadFromConfigFile(cfg, section);
	return o;
}

void VisionOptions::dump(std::ostream& out) const
{
	out << std::setprecision(17) << "patch_size_px = " << patch_size_px
	    << "\nnssd_threshold = " << nssd_threshold
	    << "\nnssd_ambiguity_margin = " << nssd_ambiguity_margin
	    << "\nsearch_n_sigma = " << search_n_sigma << "\nepipolar_band_px = " << epipolar_band_px
	    << "\nepipolar_min_depth_m = " << epipolar_min_depth_m
	    << "\nepipolar_max_depth_m = " << epipolar_max_depth_m
	    << "\nmin_corner_eigenvalue = " << min_corner_eigenvalue
	    << "\nlockon_radius_px = " << lockon_radius_px
	    << "\nfixation_max_attempts = " << fixation_max_attempts
	    << "\nfixation_search_radius_px = " << fixation_search_radius_px
	    << "\npixel_sigma_px = " << pixel_sigma_px << "\nacquire_pan_deg = " << acquire_pan_deg
	    << "\nacquire_tilt_deg = " << acquire_tilt_deg << "\nacquire_box_px = " << acquire_box_px
	    << "\nknown_search_box_px = " << known_search_box_px
	    << "\nselection = " << (selection == Selection::Saccade ? "saccade" : "largest_vs") << "\n";
}

}  // namespace mrolr::vision
