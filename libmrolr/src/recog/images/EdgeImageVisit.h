#pragma once
// EdgeImage's walk over the samples of a pose (forEachInView), shared by the scores
// (ImageVerifier.cpp) and the edge-line terms of the refinement (ImageEdgeLines.cpp).
#include <mrolr/recog/images/ImageVerifier.h>
#include <mrolr/recog/images/ProjectedRun.h>

#include <algorithm>
#include <cstdint>

namespace mrolr::recog
{
/** count()'s bilinear distance at a sample is at least its pixel's distance less √2 px: the
 * distance transform changes by at most that from a pixel to a neighbour (1.4 with DIST_MASK_5;
 * test ImageVerifier.DistanceChangesByAtMostRootTwoToANeighbour), and the four pixels
 * interpolated are the sample's and three of its neighbours. So from the cap (truncate_px) plus
 * this on, a sample costs the cap whatever the direction of its nearest edge. */
inline constexpr double kFar_px = 2;

/** What count() asks of a pixel's distance d to the nearest edge: d <= edge_distance_px (a
 * sample there may be supported), else d < the cap truncate_px + kFar_px (it may cost less than
 * the cap), else neither. */
enum Reach : std::uint8_t
{
	kClose,
	kNear,
	kBeyond
};

/** The Reach of each pixel of the distance map @p dist (CV_32F, px), as a CV_8U map. */
cv::Mat reachOf(const cv::Mat& dist, double dist_px, double truncate_px);

// the per-sample look-ups, inline: every score and edge-line term calls them per sample
inline EdgeImage::Pixel EdgeImage::pixelOf(const cv::Point2d& px)
{
	// px is inside the image (x, y >= 0): rounding half up is std::lround there
	return {static_cast<int>(px.x + 0.5), static_cast<int>(px.y + 0.5)};
}

inline bool EdgeImage::supports(const cv::Point2d& px, const cv::Point2d& tangent_px) const
{
	const Pixel at = pixelOf(px);
	return dist_.ptr<float>(at.y)[at.x] <= dist_px_ && oriented(at, tangent_px);
}

inline double EdgeImage::distanceAt(const cv::Point2d& px) const
{
	const int x0 = std::min(static_cast<int>(px.x), dist_.cols - 2);
	const int y0 = std::min(static_cast<int>(px.y), dist_.rows - 2);
	const double fx = px.x - x0, fy = px.y - y0;
	const float* r0 = dist_.ptr<float>(y0);
	const float* r1 = dist_.ptr<float>(y0 + 1);
	const auto d = [](const float* row, int x) { return static_cast<double>(row[x]); };
	return (1 - fy) * ((1 - fx) * d(r0, x0) + fx * d(r0, x0 + 1)) +
	       fy * ((1 - fx) * d(r1, x0) + fx * d(r1, x0 + 1));
}

inline std::uint8_t EdgeImage::reachAt(const Pixel& at, double truncate_px) const
{
	const std::uint8_t reach = reach_.ptr<std::uint8_t>(at.y)[at.x];
	if (truncate_px == reach_truncate_px_) return reach;
	if (truncate_px <= 0) return reach == kClose ? kClose : kBeyond;  // no cap: no kNear
	// another cap than reach_'s, from the distance itself
	const float d = dist_.ptr<float>(at.y)[at.x];
	return d <= dist_px_ ? kClose : d < truncate_px + kFar_px ? kNear : kBeyond;
}

inline bool EdgeImage::oriented(const Pixel& at, const cv::Point2d& tangent_px) const
{
	const cv::Vec2f& n = nearest_normal_.ptr<cv::Vec2f>(at.y)[at.x];  // NaN: no edge
	const double len = std::sqrt(tangent_px.x * tangent_px.x + tangent_px.y * tangent_px.y);
	if (len <= 0) return false;  // an edge seen end-on has no direction to compare
	return std::abs(n[0] * tangent_px.x + n[1] * tangent_px.y) <= sin_tol_ * len;
}

inline bool EdgeImage::occludedAt(const Pixel& at, double depth_mm) const
{
	if (!occluder_z_.data) return false;  // none (cv::Mat::empty() is a call per sample)
	return depth_mm > occluder_z_.ptr<float>(at.y)[at.x] + occluder_margin_mm_;
}

inline bool EdgeImage::hiddenBy(const SelfOcclusion& occ, const SelfOcclusion::View& view,
                                const EdgeSample& s, const SelfOcclusion::PointSight* sight) const
{
	// a limb is on the outline by construction: only the model's parts off its bodies (a handle)
	// can hide it (SelfOcclusion::hiddenLimb)
	return sight == nullptr         ? occ.hiddenLimb(view, s.p_O)
	       : revolution_visibility_ ? occ.hiddenOnBodies(view, *sight, s.p_O)
	                                : occ.hidden(view, *sight, s.p_O);
}

template <class Fn>
bool EdgeImage::forEachRun(const SightedSamples& s, const std::vector<EdgeSample>& samples,
                           const Eigen::Isometry3d& T_OinC, Fn fn) const
{
	ProjectedRun run;
	const RunProjection projection(T_OinC, K_, D_);
	for (size_t first = 0; first < samples.size(); first += ProjectedRun::kMax)
	{
		const size_t n = std::min(ProjectedRun::kMax, samples.size() - first);
		if (&samples == &s.samples_O)
			projection.project(s.blocks[first / ProjectedRun::kMax], run);
		else
			projection.project(samples.data() + first, n, run);
		if (!fn(run, first, n)) return false;
	}
	return true;
}

template <bool kHiddenToo, class Fn, class Stop>
void EdgeImage::forEachInView(const SightedSamples& ss, const Eigen::Isometry3d& T_OinL,
                              const std::vector<EdgeSample>& limbs, Fn fn, Stop stop,
                              int* outside) const
{
	const SelfOcclusion* occ = ss.occ;
	const Eigen::Isometry3d T_OinC = T_LinCcv_ * T_OinL;
	const Eigen::Vector3d c_O = T_OinL.inverse() * centre_L();
	const SelfOcclusion::View view = occ ? occ->viewFrom(c_O) : SelfOcclusion::View();
	const cv::Rect2d inside(0, 0, edges_.cols - 1, edges_.rows - 1);
	// sample j of run r (RunProjection: its point and pixels, computed for the run at once)
	const auto visit = [&](const EdgeSample& s, const SelfOcclusion::PointSight* sight,
	                       const ProjectedRun& r, size_t j)
	{
		if (!r.in_view[j] && !outside) return;
		const bool limb = sight == nullptr;
		const bool hidden = occ && hiddenBy(*occ, view, s, sight);
		if (!r.in_view[j])
		{
			*outside += hidden ? 0 : 1;
			return;
		}
		if (hidden && !kHiddenToo) return;
		const cv::Point2d px(r.u[j], r.v[j]);
		if (inside.contains(px))
			fn(px, cv::Point2d(r.tu[j], r.tv[j]), hidden, limb,
			   Eigen::Vector3d(r.x[j], r.y[j], r.z[j]));
		else if (outside && !hidden)
			++*outside;
	};
	static const SelfOcclusion::PointSight kNoSight;
	// each run is projected at once; the stop is asked after each sample, as before
	const auto walk = [&](const std::vector<EdgeSample>& samples, bool with_sights)
	{
		const auto each = [&](const ProjectedRun& run, size_t first, size_t n)
		{
			for (size_t j = 0; j < n; ++j)
			{
				const size_t k = first + j;
				visit(samples[k], !with_sights ? nullptr : occ ? &ss.sights[k] : &kNoSight, run, j);
				if (stop()) return false;
			}
			return true;
		};
		return forEachRun(ss, samples, T_OinC, each);
	};
	if (walk(ss.samples_O, true)) walk(limbs, false);
}

}  // namespace mrolr::recog
