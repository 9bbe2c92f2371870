#include <mrolr/stereo/Fit3.h>
#include <mrolr/util/OptionsBinder.h>

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

namespace
{
using O = FitOptions;
constexpr auto kOpt = util::Presence::Optional;  // [scene]: docs/config.md

const util::OptionsBinder<O>& fitOptionsBinder()
{
	static const auto b = util::OptionsBinder<O>()
	    .number("line_tol_px", &O::line_tol_px, 0.05, 50, kOpt)
	    .number("conic_tol_px", &O::conic_tol_px, 0.05, 50, kOpt)
	    .number("min_arc_deg", &O::min_arc_deg, 0, 360, kOpt)
	    .number("max_conic_radius_px", &O::max_conic_radius_px, 1, 1e5, kOpt)
	    .integer("min_line_edgels", &O::min_line_edgels, 3, 1000000, kOpt)
	    .integer("min_conic_edgels", &O::min_conic_edgels, 6, 1000000, kOpt)
	    .number("max_rms_mm", &O::max_rms_mm, 0, 1e4, kOpt)
	    .integer("max_gap_edgels", &O::max_gap_edgels, 0, 1000000, kOpt)
	    .number("max_disparity_jump_px", &O::max_disparity_jump_px, 0, 1e4, kOpt);
	return b;
}
}  // namespace

void FitOptions::loadFromConfigFile(const mrpt::config::CConfigFileBase& cfg,
                                   const std::string& section)
{
	fitOptionsBinder().load(cfg, section, *this);
}

void FitOptions::dump(std::ostream& out) const
{
	fitOptionsBinder().dump(out, *this);
}

}  // namespace mrolr::stereo
