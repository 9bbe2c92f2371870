#include <mrolr/model/TurntableRimChords.h>
#include <mrolr/util/OptionsBinder.h>

#include <Eigen/QR>

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <set>

namespace mrolr::model
{
namespace
{
struct Chord
{
	size_t view, line;
	double z;
	Eigen::Vector2d e;  // unit horizontal direction across the view
	double s1, s2;      // span along e, s1 <= s2
};

std::vector<Chord> chordsOf(const std::vector<WireFrame>& views,
                            const std::vector<ViewEdges>& edges, const RimChordOptions& o)
{
	std::vector<Chord> out;
	const double max_dz = std::sin(o.max_slope_deg * M_PI / 180);
	for (size_t v = 0; v < views.size() && v < edges.size(); ++v)
	{
		const Eigen::Vector3d cam = edges[v].T_OinL.inverse().translation();
		for (size_t i = 0; i < views[v].lines.size(); ++i)
		{
			const Line3& l = views[v].lines[i];
			if (l.length() < 1e-6 || std::abs(l.direction().z()) > max_dz) continue;
			const Eigen::Vector3d mid = 0.5 * (l.p1 + l.p2);
			const Eigen::Vector2d d = (mid - cam).head<2>();
			if (d.norm() < 1e-6) continue;
			const Eigen::Vector2d e = Eigen::Vector2d(-d.y(), d.x()).normalized();
			const double a = l.p1.head<2>().dot(e), b = l.p2.head<2>().dot(e);
			out.push_back({v, i, mid.z(), e, std::min(a, b), std::max(a, b)});
		}
	}
	return out;
}

struct Span
{
	Eigen::Vector2d e;
	double s1, s2;
};

/** One span per view: the union of its chords at this height (pieces of one flat ellipse). */
std::vector<Span> spansOf(const std::vector<Chord>& chords, const std::vector<size_t>& group)
{
	std::map<size_t, Span> by_view;
	for (size_t i : group)
	{
		const Chord& c = chords[i];
		auto [it, fresh] = by_view.try_emplace(c.view, Span{c.e, c.s1, c.s2});
		if (!fresh)
		{
			it->second.s1 = std::min(it->second.s1, c.s1);
			it->second.s2 = std::max(it->second.s2, c.s2);
		}
	}
	std::vector<Span> spans;
	for (const auto& [v, s] : by_view) spans.push_back(s);
	return spans;
}

/** Least-squares centre of the spans: c·e = (s1 + s2) / 2 (a constant bias of the spans across
 * the views, one end cut short where the lit side ends, cancels over views all around). */
Eigen::Vector2d centreOf(const std::vector<Span>& spans)
{
	Eigen::MatrixXd A(spans.size(), 2);
	Eigen::VectorXd b(spans.size());
	for (size_t k = 0; k < spans.size(); ++k)
	{
		A.row(static_cast<long>(k)) = spans[k].e.transpose();
		b(static_cast<long>(k)) = 0.5 * (spans[k].s1 + spans[k].s2);
	}
	return A.colPivHouseholderQr().solve(b);
}

/** Largest difference between a span's middle and half width and those of the circle (c0, half)
 * seen across that view: the chords of a round rim agree, those of a box's edges do not. */
double spanMisfit(const std::vector<Span>& spans, const Eigen::Vector2d& c0, double half)
{
	double worst = 0;
	for (const auto& s : spans)
		worst = std::max({worst, std::abs(0.5 * (s.s1 + s.s2) - c0.dot(s.e)),
		                  std::abs(0.5 * (s.s2 - s.s1) - half)});
	return worst;
}

bool heightKnown(const std::vector<Conic3>& known, double z, double tol)
{
	return std::any_of(known.begin(), known.end(),
	                   [&](const Conic3& k)
	                   {
		                   return std::abs(k.normal.normalized().z()) > 0.98 &&
		                          std::abs(k.centre.z() - z) <= tol;
	                   });
}

/** The horizontal circle near the chords' height, centre and at least their half width that the
 * images show over most 10° pieces (searched in 1 mm / 0.5 mm steps). */
std::optional<Conic3> rimAt(const std::vector<Chord>& chords, const std::vector<size_t>& group,
                            const std::vector<ViewEdges>& edges, const std::vector<Conic3>& known,
                            const RimChordOptions& o, const RimImageOptions& io)
{
	const auto spans = spansOf(chords, group);
	if (static_cast<int>(spans.size()) < std::max(o.min_views, 2)) return std::nullopt;
	double z = 0, half = 0;
	for (size_t i : group) z += chords[i].z;
	z /= static_cast<double>(group.size());
	if (heightKnown(known, z, o.height_tol_mm)) return std::nullopt;
	for (const auto& s : spans) half = std::max(half, 0.5 * (s.s2 - s.s1));
	const Eigen::Vector2d c0 = centreOf(spans);
	if (spanMisfit(spans, c0, half) > o.span_tol_mm) return std::nullopt;
	const double r_lo = std::max(o.min_radius_mm, half - o.tol_mm);
	const double r_hi = std::min(o.max_radius_mm, half * o.max_radius_ratio);
	const int nc = static_cast<int>(std::floor(o.tol_mm)), nz = static_cast<int>(o.height_tol_mm);
	std::optional<Conic3> best;
	int best_n = 0;
	double best_g = 0;
	for (int dz = -nz; dz <= nz; ++dz)
		for (int dx = -nc; dx <= nc; ++dx)
			for (int dy = -nc; dy <= nc; ++dy)
				for (double r = r_lo; r <= r_hi; r += 0.5)
				{
					const Eigen::Vector3d centre(c0.x() + dx, c0.y() + dy, z + dz);
					Conic3 rim{0, centre, Eigen::Vector3d::UnitZ(), Eigen::Vector3d::UnitX(),
					           r, r, 0, 0};
					const int n = arcFromImages(rim, edges, io);
					if (n * 10.0 < o.min_image_arc_deg) continue;
					const double g = meanFacingGradient(rim, edges, io);
					if (g > best_g) best_g = g, best_n = n, best = rim;
				}
	if (!best || best_n * 10.0 < o.min_image_arc_deg) return std::nullopt;
	return best;
}
}  // namespace

namespace
{
using R = RimChordOptions;
constexpr auto kOpt = util::Presence::Optional;  // [turntable]: every key of config/model.ini

const util::OptionsBinder<R>& rimChordOptionsBinder()
{
	static const auto b =
	    util::OptionsBinder<R>()
	        .integer("rim_chord_min_views", &R::min_views, 0, 1000, kOpt)
	        .number("rim_chord_max_slope_deg", &R::max_slope_deg, 0, 45, kOpt)
	        .number("rim_chord_height_tol_mm", &R::height_tol_mm, 0.01, 100, kOpt)
	        .number("rim_chord_tol_mm", &R::tol_mm, 0.01, 100, kOpt)
	        .number("rim_chord_min_image_arc_deg", &R::min_image_arc_deg, 0, 360, kOpt)
	        .number("rim_chord_max_radius_ratio", &R::max_radius_ratio, 1, 10, kOpt)
	        .number("rim_chord_span_tol_mm", &R::span_tol_mm, 0.01, 100, kOpt);
	return b;
}
}  // namespace

void RimChordOptions::loadFromConfigFile(const mrpt::config::CConfigFileBase& cfg,
                                         const std::string& s)
{
	rimChordOptionsBinder().load(cfg, s, *this);
}

std::vector<Conic3> rimsFromChords(const std::vector<WireFrame>& views,
                                   const std::vector<ViewEdges>& edges,
                                   const std::vector<Conic3>& known, const RimChordOptions& o,
                                   const RimImageOptions& image_options)
{
	std::vector<Conic3> rims;
	if (o.min_views <= 0 || image_options.min_gradient <= 0 || edges.size() != views.size())
		return rims;
	const auto chords = chordsOf(views, edges, o);
	std::set<size_t> used;
	for (size_t seed = 0; seed < chords.size(); ++seed)
	{
		if (used.count(seed)) continue;
		std::vector<size_t> group;
		for (size_t i = 0; i < chords.size(); ++i)
			if (!used.count(i) && std::abs(chords[i].z - chords[seed].z) <= o.height_tol_mm)
				group.push_back(i);
		auto all_known = known;
		all_known.insert(all_known.end(), rims.begin(), rims.end());
		const auto rim = rimAt(chords, group, edges, all_known, o, image_options);
		if (!rim) continue;
		rims.push_back(*rim);
		for (size_t i : group) used.insert(i);
	}
	return rims;
}

}  // namespace mrolr::model
