#pragma once
/** Parameters of the image-level measurement pipeline (thesis 5.2–5.3, 5.5.4), read from section
 * [vision] of config/slam.ini. Every key carries its unit; a missing or malformed key is a
 * mrolr::util::ConfigError naming file, section and key. */

#include <mrpt/config/CConfigFileBase.h>

#include <iosfwd>
#include <string>

namespace mrolr::vision
{
/** How the live cycle picks the feature to measure (thesis 5.7). */
enum class Selection
{
	LargestVs,  ///< the visible feature with the largest Vs (eq 5.147) at every step
	Saccade     ///< 5.7 steps 1–4 (slam::decideSaccade): saccades cost measurements
};

/** Patch size, NSSD threshold, search regions and the fixation loop. Defaults are the thesis's. */
struct VisionOptions
{
	int patch_size_px = 13;       ///< side of the square feature patch (5.2: 13×13)
	double nssd_threshold = 0.9;  ///< best NSSD (eq 5.21) below this wins (5.2.1, [Dav98 p45])
	/** Optional key: a feature match (measureInImages) is refused as ambiguous when another place
	 * of the search ellipse, more than half a patch away, scores within this of the best NSSD in
	 * either image (repeated texture); 0 = off (the thesis). */
	double nssd_ambiguity_margin = 0;
	double search_n_sigma = 3;    ///< half-axes of the search ellipse in σ (eqs 5.37–5.39)
	double epipolar_band_px = 7;  ///< right-image search within ± this of the epipolar line (5.3)
	double epipolar_min_depth_m = 0.3;    ///< nearest depth along the left ray that is searched
	double epipolar_max_depth_m = 30;     ///< farthest depth along the left ray that is searched
	double min_corner_eigenvalue = 1e-3;  ///< smallest acceptable λ_min of eq 5.20 (OpenCV scale)
	double lockon_radius_px = 2;    ///< lock-on: patch centre this close to (u0, v0) in both (5.3)
	int fixation_max_attempts = 4;  ///< fixation retries before the feature is discarded (5.3)
	double fixation_search_radius_px = 40;  ///< half-side of the box searched after a saccade
	double pixel_sigma_px = 1.0;   ///< matching noise per image coordinate, for triangulation
	double acquire_pan_deg = 30;   ///< new features are sought at pan +this, 0, −this (5.7)
	double acquire_tilt_deg = 10;  ///< … with the head tilted up by this
	int acquire_box_px = 200;  ///< side of the central left-image box searched for a new feature
	/** Side of the box around a fixated known landmark's centre in which its stored patch is the
	 * best Shi–Tomasi corner (1: the centre itself), pixels (5.6.2). */
	int known_search_box_px = 21;
	/** Key `selection = largest_vs | saccade`. With saccade, the measurements a saccade loses
	 * (head speed model of [slam]) are really skipped. */
	Selection selection = Selection::LargestVs;

	/** Reads every key above from @p section; all keys are required. */
	void loadFromConfigFile(const mrpt::config::CConfigFileBase& cfg, const std::string& section);

	/** Loads section @p section of the .ini file @p path (ConfigError if the file is missing). */
	static VisionOptions fromFile(const std::string& path, const std::string& section = "vision");

	/** Writes the keys as `key = value` lines, readable back by loadFromConfigFile. */
	void dump(std::ostream& out) const;
};

}  // namespace mrolr::vision
