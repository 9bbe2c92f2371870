// The yaw sweep's score (ImageVerifier::scoreIfMore): a yaw's score is wanted only when it can
// beat the sweep's best by supported count or by supported fraction (ScoreCap). Its Prospects
// bound both before the sight tests, and the tests are made only until the bounds rule it out.
// The answer is the same as ScoreCap's: empty exactly when the complete count exceeds the cap,
// else score().
#include <mrolr/recog/images/ImageVerifier.h>
#include <mrolr/recog/images/Prospects.h>

#include "EdgeImageVisit.h"

#include <array>

namespace mrolr::recog
{
namespace
{
/** Below this a bound is not trusted to decide; the complete counts decide then (an early bound
 * compares sums of a few thousand samples at most: rounding is far below it). */
constexpr double kBoundMargin = 1e-6;
}  // namespace

void EdgeImage::prospects(const SightedSamples& ss, const Eigen::Isometry3d& T_OinL,
                          const std::vector<EdgeSample>& limbs, Prospects& out) const
{
	out.on_edge.clear(), out.off_edge.clear();
	const Eigen::Isometry3d T_OinC = T_LinCcv_ * T_OinL;
	const cv::Rect2d inside(0, 0, edges_.cols - 1, edges_.rows - 1);
	ProjectedRun r;
	// forEachInView's walk without the sight tests: in view, inside the image, not occluded
	const auto walk = [&](const std::vector<EdgeSample>& samples, bool with_sights, size_t offset)
	{
		for (size_t first = 0; first < samples.size(); first += ProjectedRun::kMax)
		{
			const size_t n = std::min(ProjectedRun::kMax, samples.size() - first);
			if (with_sights)
				projectRun(T_OinC, K_, D_, ss.blocks[first / ProjectedRun::kMax], r);
			else
				projectRun(T_OinC, K_, D_, samples.data() + first, n, r);
			for (size_t j = 0; j < n; ++j)
			{
				const cv::Point2d px(r.u[j], r.v[j]);
				if (!r.in_view[j] || !inside.contains(px)) continue;
				const Pixel at = pixelOf(px);
				if (occludedAt(at, r.z[j])) continue;
				const auto k = static_cast<std::uint32_t>(offset + first + j);
				// the distance first: most samples of a yaw that fits badly are far from edges
				const bool on_edge = dist_.ptr<float>(at.y)[at.x] <= dist_px_ &&
				                     oriented(at, cv::Point2d(r.tu[j], r.tv[j]));
				(on_edge ? out.on_edge : out.off_edge).push_back(k);
			}
		}
	};
	walk(ss.samples_O, true, 0);
	walk(limbs, false, ss.samples_O.size());
}

bool EdgeImage::hides(const SightedSamples& s, const std::vector<EdgeSample>& limbs,
                      const SelfOcclusion::View& view, std::uint32_t k) const
{
	if (!s.occ) return false;
	const size_t n = s.samples_O.size();
	return k < n ? hiddenBy(*s.occ, view, s.samples_O[k], &s.sights[k])
	             : hiddenBy(*s.occ, view, limbs[k - n], nullptr);
}

bool EdgeImage::seenAtOnce(const SightedSamples& s, const SelfOcclusion::View& view,
                           std::uint32_t k) const
{
	if (!s.occ) return true;
	// a limb's test and one against the bodies of revolution have no such first step
	if (k >= s.samples_O.size()) return false;
	const SelfOcclusion::PointSight& sight = s.sights[k];
	if (revolution_visibility_ && sight.on_bodies) return false;
	return SelfOcclusion::sharesOutsideFace(view, sight);
}

std::optional<ImageScore> ImageVerifier::scoreIfMore(const SightedSamples& samples,
                                                     const Eigen::Isometry3d& T_OinL,
                                                     int min_supported, double max_score) const
{
	ScoreCap cap;
	cap.min_supported = min_supported, cap.max_fraction = max_score;
	// the fraction's bound below holds for a fraction of at most 1
	if (!(max_score <= 1)) return scoreUnlessExceeded(samples, T_OinL, cap);
	static thread_local std::array<std::vector<EdgeSample>, 2> limbs;
	static thread_local std::array<Prospects, 2> p;
	int supported_max = 0, unhidden_off = 0;
	for (size_t i = 0; i < 2; ++i)
	{
		images_[i].limbsSeen(samples, T_OinL, limbs[i]);
		images_[i].prospects(samples, T_OinL, limbs[i], p[i]);
		supported_max += static_cast<int>(p[i].on_edge.size());
	}
	const auto viewOf = [&](size_t i)
	{
		return samples.occ ? samples.occ->viewFrom(T_OinL.inverse() * images_[i].centre_L())
		                   : SelfOcclusion::View();
	};
	const std::array<SelfOcclusion::View, 2> views{viewOf(0), viewOf(1)};
	// ScoreCap's fraction test, S <= max_score·C·(1 − 1e-12) with C = S + the unhidden ones off
	// the edges: it holds for the complete counts once it holds here (by the margin), since S
	// can only fall to its final value and the unhidden ones only rise to theirs
	const auto fractionRuledOut = [&]
	{
		return supported_max <=
		       max_score * (supported_max + unhidden_off) * (1 - 1e-12) - kBoundMargin;
	};
	// the supported ones are tested until too few are left to beat min_supported ...
	std::array<size_t, 2> tested = {0, 0};
	for (size_t i = 0; i < 2 && supported_max >= min_supported; ++i)
		for (; tested[i] < p[i].on_edge.size() && supported_max >= min_supported; ++tested[i])
			supported_max -=
			    images_[i].hides(samples, limbs[i], views[i], p[i].on_edge[tested[i]]) ? 1 : 0;
	if (supported_max >= min_supported) return score(samples, T_OinL);
	// ... then the others until the fraction is ruled out (those seen at once first), then the
	// rest of the supported ones
	static thread_local std::array<std::vector<std::uint32_t>, 2> later;
	for (size_t i = 0; i < 2; ++i)
	{
		later[i].clear();
		for (const std::uint32_t q : p[i].off_edge)
		{
			if (!images_[i].seenAtOnce(samples, views[i], q))
			{
				later[i].push_back(q);
				continue;
			}
			++unhidden_off;
			if (fractionRuledOut()) return std::nullopt;
		}
	}
	for (size_t i = 0; i < 2; ++i)
		for (const std::uint32_t q : later[i])
		{
			unhidden_off += images_[i].hides(samples, limbs[i], views[i], q) ? 0 : 1;
			if (fractionRuledOut()) return std::nullopt;
		}
	for (size_t i = 0; i < 2; ++i)
		for (; tested[i] < p[i].on_edge.size(); ++tested[i])
		{
			supported_max -=
			    images_[i].hides(samples, limbs[i], views[i], p[i].on_edge[tested[i]]) ? 1 : 0;
			if (fractionRuledOut()) return std::nullopt;
		}
	// every sight tested: the complete counts, decided as ScoreCap decides them
	cap.supported = supported_max, cap.considered = supported_max + unhidden_off;
	if (cap.exceeded()) return std::nullopt;
	return score(samples, T_OinL);
}

}  // namespace mrolr::recog
