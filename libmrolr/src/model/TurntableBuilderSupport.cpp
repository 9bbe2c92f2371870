#include <mrolr/model/TurntableBuilderSupport.h>
#include <mrolr/model/WireFrameSampling.h>
#include <mrolr/util/OptionsBinder.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace mrolr::model
{
namespace
{
constexpr double kSampleStepMm = 2.0;

/** Is sample @p s steep (its tangent within steep_max_deg of the turntable axis, O's z)? Only such
 * pieces can be contour generators of an upright surface of revolution. */
bool steep(const FeatureSample& s, const ViewSupportOptions& o)
{
	return std::abs(s.tangent.z()) >= std::cos(o.steep_max_deg * M_PI / 180);
}

/** Share (by count) of @p samples that have a sample of @p other near with a parallel tangent;
 * steep samples count only when @p other is a near view. */
double supportedShare(const std::vector<FeatureSample>& samples,
                      const std::vector<FeatureSample>& other, bool near_view,
                      const ViewSupportOptions& o)
{
	const double min_cos = std::cos(o.max_tangent_deg * M_PI / 180), tol2 = o.tol_mm * o.tol_mm;
	size_t n = 0;
	for (const auto& s : samples)
	{
		if (!near_view && steep(s, o)) continue;
		n += std::any_of(other.begin(), other.end(),
		                 [&](const FeatureSample& q) {
			                 return (s.p - q.p).squaredNorm() <= tol2 &&
			                        std::abs(s.tangent.dot(q.tangent)) >= min_cos;
		                 });
	}
	return samples.empty() ? 0.0 : static_cast<double>(n) / samples.size();
}

std::vector<FeatureSample> featureSamples(const WireFrame& wf, size_t i)
{
	const int id = static_cast<int>(i);
	return i < wf.lines.size() ? sampleLine(wf.lines[i], kSampleStepMm, id)
	                           : sampleConic(wf.conics[i - wf.lines.size()], kSampleStepMm, id);
}

template <typename T>
void eraseMarked(std::vector<T>& v, const std::vector<bool>& drop, size_t offset)
{
	std::vector<T> kept;
	for (size_t i = 0; i < v.size(); ++i)
		if (!drop[offset + i]) kept.push_back(v[i]);
	v = std::move(kept);
}
}  // namespace

namespace
{
using V = ViewSupportOptions;
constexpr auto kOpt = util::Presence::Optional;  // [turntable]: every key of config/model.ini

const util::OptionsBinder<V>& viewSupportOptionsBinder()
{
	static const auto b =
	    util::OptionsBinder<V>()
	        .number("support_tol_mm", &V::tol_mm, 0.01, 1e3, kOpt)
	        .number("support_max_tangent_deg", &V::max_tangent_deg, 0, 90, kOpt)
	        .number("support_max_view_angle_deg", &V::max_view_angle_deg, 0, 180, kOpt)
	        .number("support_min_fraction", &V::min_fraction, 0, 1, kOpt)
	        .number("support_steep_max_deg", &V::steep_max_deg, 0, 90, kOpt)
	        .number("support_image_gradient", &V::image_min_gradient, 0, 1e4, kOpt)
	        .integer("min_views", &V::min_views, 1, 1000, kOpt);
	return b;
}
}  // namespace

void ViewSupportOptions::loadFromConfigFile(const mrpt::config::CConfigFileBase& cfg,
                                            const std::string& s)
{
	viewSupportOptionsBinder().load(cfg, s, *this);
}

void ViewSupportOptions::dump(std::ostream& out) const
{
	viewSupportOptionsBinder().dump(out, *this);
}

double turntableAngleBetween(double a_deg, double b_deg)
{
	const double d = std::fmod(std::abs(a_deg - b_deg), 360.0);
	return d > 180 ? 360 - d : d;
}

namespace
{
/** Views (other than @p own) supporting @p samples; with @p any_view steep pieces count from every
 * view, otherwise only from near views. */
int supportingViews(const std::vector<std::vector<FeatureSample>>& view_samples,
                    const std::vector<double>& angles_deg, size_t own,
                    const std::vector<FeatureSample>& samples, bool any_view,
                    const ViewSupportOptions& o)
{
	int n = 0;
	for (size_t j = 0; j < view_samples.size(); ++j)
	{
		if (j == own) continue;
		const bool near_view = any_view || turntableAngleBetween(angles_deg[j], angles_deg[own]) <=
		                                       o.max_view_angle_deg;
		n += supportedShare(samples, view_samples[j], near_view, o) >= o.min_fraction;
	}
	return n;
}

/** Do the left images of the near views show an edge along the steep pieces of @p samples? */
bool edgeInNearImages(const std::vector<FeatureSample>& samples, size_t own,
                      const std::vector<double>& angles_deg, const std::vector<ViewEdges>& edges,
                      const ViewSupportOptions& o)
{
	std::vector<FeatureSample> steep_part;
	for (const auto& s : samples)
		if (steep(s, o)) steep_part.push_back(s);
	if (steep_part.empty()) return true;
	for (size_t j = 0; j < edges.size(); ++j)
		if (j != own &&
		    turntableAngleBetween(angles_deg[j], angles_deg[own]) <= o.max_view_angle_deg &&
		    imageEdgeShare(steep_part, edges[j], o.image_min_gradient) >= o.min_fraction)
			return true;
	return false;
}

/** Samples of every view; of its conics only with @p conics_only. */
std::vector<std::vector<FeatureSample>> samplesOfViews(const std::vector<WireFrame>& views,
                                                       bool conics_only = false)
{
	std::vector<std::vector<FeatureSample>> out;
	for (auto v : views)
	{
		if (conics_only) v.lines.clear();
		out.push_back(sampleWireFrame(v, kSampleStepMm));
	}
	return out;
}

/** Is feature @p samples of view @p own seen in min_views views? Steep pieces seen only from far
 * views count when the near views' images show an edge there (a fixed edge, not a contour). */
bool seenEnough(const std::vector<std::vector<FeatureSample>>& view_samples,
                const std::vector<double>& angles_deg, size_t own,
                const std::vector<FeatureSample>& samples, const std::vector<ViewEdges>& edges,
                const ViewSupportOptions& o)
{
	if (supportingViews(view_samples, angles_deg, own, samples, false, o) + 1 >= o.min_views)
		return true;
	return !edges.empty() &&
	       supportingViews(view_samples, angles_deg, own, samples, true, o) + 1 >= o.min_views &&
	       edgeInNearImages(samples, own, angles_deg, edges, o);
}
}  // namespace

int supportingViews(const std::vector<WireFrame>& views, const std::vector<double>& angles_deg,
                    size_t own, size_t feature, const ViewSupportOptions& o)
{
	return supportingViews(samplesOfViews(views), angles_deg, own,
	                       featureSamples(views[own], feature), false, o);
}

size_t keepFeaturesSeenFromNearViews(std::vector<WireFrame>& views,
                                     const std::vector<double>& angles_deg,
                                     const ViewSupportOptions& o,
                                     const std::vector<ViewEdges>& edges)
{
	if (angles_deg.size() != views.size() || (!edges.empty() && edges.size() != views.size()))
		throw std::invalid_argument("keepFeaturesSeenFromNearViews: one angle (image) per view");
	// a conic must be seen as an arc in other views too: a thin ellipse fitted to straight strokes
	// would otherwise be supported by the lines of the strokes
	const auto all_samples = samplesOfViews(views), arc_samples = samplesOfViews(views, true);
	size_t removed = 0;
	for (size_t k = 0; k < views.size(); ++k)
	{
		std::vector<bool> drop;
		for (size_t i = 0; i < featureCount(views[k]); ++i)
			drop.push_back(!seenEnough(i < views[k].lines.size() ? all_samples : arc_samples,
			                           angles_deg, k, featureSamples(views[k], i), edges, o));
		removed += static_cast<size_t>(std::count(drop.begin(), drop.end(), true));
		const size_t n_lines = views[k].lines.size();
		eraseMarked(views[k].lines, drop, 0);
		eraseMarked(views[k].conics, drop, n_lines);
	}
	return removed;
}

}  // namespace mrolr::model
