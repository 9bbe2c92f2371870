#include <mrolr/stereo/Fit3.h>
#include <mrolr/util/Config.h>

#include <ostream>

namespace mrolr::stereo
{
namespace
{
/** Index in [lo, hi) of the edgel farthest from the chord lo → hi−1 (from edgel lo when the string
 * closes on itself). */
size_t farthest(const std::vector<StereoEdgel>& e, size_t lo, size_t hi)
{
	const cv::Point2d a = e[lo].xy_px, b = e[hi - 1].xy_px, ab = b - a;
	const double len = cv::norm(ab);
	size_t best = (lo + hi) / 2;
	double best_d = -1;
	for (size_t i = lo + 1; i + 1 < hi; ++i)
	{
		const cv::Point2d q = e[i].xy_px - a;
		const double dist = len > 2 ? std::abs(q.cross(ab)) / len : cv::norm(q);
		if (dist > best_d) best_d = dist, best = i;
	}
	return best;
}

void split(const std::vector<StereoEdgel>& e, size_t lo, size_t hi, const Rectifier& rect,
           const FitOptions& o, std::vector<LineFit3>& lines, std::vector<ConicFit3>& conics)
{
	if (hi - lo < static_cast<size_t>(std::max(3, o.min_line_edgels))) return;
	const std::vector<StereoEdgel> piece(e.begin() + static_cast<long>(lo),
	                                     e.begin() + static_cast<long>(hi));
	if (auto l = fitLine3(piece, rect, o)) return lines.push_back(*l);
	if (auto c = fitConic3(piece, rect, o)) return conics.push_back(*c);
	const size_t k = farthest(e, lo, hi);
	split(e, lo, k, rect, o, lines, conics);
	split(e, k, hi, rect, o, lines, conics);
}
}  // namespace

void segmentString(const std::vector<StereoEdgel>& e, const Rectifier& rect, const FitOptions& o,
                   std::vector<LineFit3>& lines, std::vector<ConicFit3>& conics)
{
	split(e, 0, e.size(), rect, o, lines, conics);
}

void FitOptions::loadFromConfigFile(const mrpt::config::CConfigFileBase& cfg,
                                    const std::string& section)
{
	auto rd = [&](const char* k, double& v) { v = util::readDouble(cfg, section, k, v); };
	auto ri = [&](const char* k, int& v)
	{ v = static_cast<int>(util::readInt(cfg, section, k, v)); };
	rd("line_tol_px", line_tol_px);
	rd("conic_tol_px", conic_tol_px);
	rd("min_arc_deg", min_arc_deg);
	rd("max_conic_radius_px", max_conic_radius_px);
	ri("min_line_edgels", min_line_edgels);
	ri("min_conic_edgels", min_conic_edgels);
	rd("max_rms_mm", max_rms_mm);
	ri("max_gap_edgels", max_gap_edgels);
	rd("max_disparity_jump_px", max_disparity_jump_px);
	util::requireInRange(cfg, section, "line_tol_px", line_tol_px, 0.05, 50);
	util::requireInRange(cfg, section, "min_line_edgels", min_line_edgels, 3, 1e6);
	util::requireInRange(cfg, section, "min_conic_edgels", min_conic_edgels, 6, 1e6);
}

void FitOptions::dump(std::ostream& out) const
{
	out << "line_tol_px = " << line_tol_px << "\nconic_tol_px = " << conic_tol_px
	    << "\nmin_arc_deg = " << min_arc_deg << "\nmax_conic_radius_px = " << max_conic_radius_px
	    << "\nmin_line_edgels = " << min_line_edgels << "\nmin_conic_edgels = " << min_conic_edgels
	    << "\nmax_rms_mm = " << max_rms_mm << "\nmax_gap_edgels = " << max_gap_edgels
	    << "\nmax_disparity_jump_px = " << max_disparity_jump_px << "\n";
}

}  // namespace mrolr::stereo
