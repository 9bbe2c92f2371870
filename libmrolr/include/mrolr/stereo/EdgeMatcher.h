#pragma once
/** Edge-based stereo matching along rectified scanlines with a disparity-gradient limit, after the
 * PMF algorithm used by TINA's Edge Tool (thesis 4.3.2.3, [PMF85]). Every edgel that crosses a
 * scanline is a sample; candidate matches on the same scanline must lie in the disparity range and
 * have similar gradient direction and the same contrast sign. Each candidate gathers support
 * Σ 1/r from neighbouring candidates within support_radius_px whose disparity gradient
 * |d − d'| / r (r: cyclopean separation, px) is below the limit; matches are then accepted in order
 * of support, each left and right sample used once (uniqueness). */

#include <mrolr/stereo/EdgeStrings.h>

#include <mrpt/config/CConfigFileBase.h>

#include <iosfwd>
#include <string>
#include <vector>

namespace mrolr::stereo
{
struct MatchOptions
{
	double disparity_gradient_limit = 1.0;  ///< PMF limit (< 2; 0.5–1 typical)
	double support_radius_px = 12;          ///< neighbourhood searched for support
	double max_orientation_diff_deg = 30;   ///< gradient directions of a match
	double min_edge_angle_deg = 12;  ///< edges closer than this to the scanline are not matched
	double min_support = 0.3;        ///< matches with less support are rejected

	void loadFromConfigFile(const mrpt::config::CConfigFileBase& cfg, const std::string& section);
	void dump(std::ostream& out) const;
};

/** One accepted match: the left edgel (string and index in it), its scanline crossing and the
 * disparity d = x_left − x_right (px). */
struct EdgeMatch
{
	int string = 0;
	int edgel = 0;
	double x_left_px = 0, y_px = 0;
	double disparity_px = 0;
	double support = 0;
};

/** Matches rectified left and right edge strings for disparities in [d_min_px, d_max_px]. Result
 * sorted by (string, edgel). */
std::vector<EdgeMatch> matchEdgeStrings(const std::vector<EdgeString>& left,
                                        const std::vector<EdgeString>& right, double d_min_px,
                                        double d_max_px, const MatchOptions& options);

}  // namespace mrolr::stereo
