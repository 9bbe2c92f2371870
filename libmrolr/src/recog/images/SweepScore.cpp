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

/** A yaw's counts in both images as its prospects' sight tests narrow them: at most
 * supportedMax() samples supported, at least unhidden_off_ considered and unsupported. */
class YawBound
{
 public:
	using Limbs = std::array<std::vector<EdgeSample>, 2>;
	using Both = std::array<Prospects, 2>;
	using Views = std::array<SelfOcclusion::View, 2>;

	YawBound(const std::vector<EdgeImage>& images, const SightedSamples& s, const Limbs& limbs,
	         const Both& p, const Views& views)
	    : images_(images), s_(s), limbs_(limbs), p_(p), views_(views)
	{
		for (const Prospects& q : p) supported_max_ += static_cast<int>(q.on_edge.size());
	}

	/** Tests the supported ones until fewer than @p min_supported can be left: false when all are
	 * tested and as many are left (the yaw beats the count). */
	bool countRuledOut(int min_supported)
	{
		for (size_t i = 0; i < 2 && supported_max_ >= min_supported; ++i)
			for (; tested_[i] < p_[i].on_edge.size() && supported_max_ >= min_supported;
			     ++tested_[i])
				supported_max_ -= hides(i, p_[i].on_edge[tested_[i]]) ? 1 : 0;
		return supported_max_ < min_supported;
	}

	/** Tests the others until ScoreCap's fraction test, S <= @p max_score (at most 1) · C ·
	 * (1 − 1e-12) with C = S + the unhidden ones off the edges, holds for the complete counts
	 * (it does once it holds here by the margin: S can only fall to its final value and the
	 * unhidden ones only rise to theirs); those seen at once first, then the rest of the
	 * supported ones. False when every sight is tested and it does not hold by the margin. */
	bool fractionRuledOut(double max_score)
	{
		const auto holds = [&]
		{
			return supported_max_ <=
			       max_score * (supported_max_ + unhidden_off_) * (1 - 1e-12) - kBoundMargin;
		};
		static thread_local std::array<std::vector<std::uint32_t>, 2> later;
		for (size_t i = 0; i < 2; ++i)
		{
			later[i].clear();
			for (const std::uint32_t q : p_[i].off_edge)
			{
				if (!images_[i].seenAtOnce(s_, views_[i], q))
				{
					later[i].push_back(q);
					continue;
				}
				++unhidden_off_;
				if (holds()) return true;
			}
		}
		for (size_t i = 0; i < 2; ++i)
			for (const std::uint32_t q : later[i])
			{
				unhidden_off_ += hides(i, q) ? 0 : 1;
				if (holds()) return true;
			}
		for (size_t i = 0; i < 2; ++i)
			for (; tested_[i] < p_[i].on_edge.size(); ++tested_[i])
			{
				supported_max_ -= hides(i, p_[i].on_edge[tested_[i]]) ? 1 : 0;
				if (holds()) return true;
			}
		return false;
	}

	int supportedMax() const { return supported_max_; }
	int consideredMin() const { return supported_max_ + unhidden_off_; }

 private:
	bool hides(size_t i, std::uint32_t k) const
	{
		return images_[i].hides(s_, limbs_[i], views_[i], k);
	}

	const std::vector<EdgeImage>& images_;
	const SightedSamples& s_;
	const Limbs& limbs_;
	const Both& p_;
	const Views& views_;
	int supported_max_ = 0, unhidden_off_ = 0;
	std::array<size_t, 2> tested_ = {0, 0};  ///< the supported ones tested, per image
};
}  // namespace

void EdgeImage::prospects(const SightedSamples& ss, const Eigen::Isometry3d& T_OinL,
                          const std::vector<EdgeSample>& limbs, Prospects& out) const
{
	// written through raw pointers, with every bound and map in a local (the writes through a
	// vector or a capture would have them reloaded at each sample), then cut to length
	const size_t total = ss.samples_O.size() + limbs.size();
	out.on_edge.resize(total), out.off_edge.resize(total);
	std::uint32_t *on = out.on_edge.data(), *off = out.off_edge.data();
	size_t n_on = 0, n_off = 0;
	const Eigen::Isometry3d T_OinC = T_LinCcv_ * T_OinL;
	// cv::Rect2d(0, 0, cols − 1, rows − 1).contains
	const double max_u = edges_.cols - 1, max_v = edges_.rows - 1;
	const std::uint8_t* const reach = reach_.data;
	const size_t reach_step = reach_.step[0];
	const bool occluders = occluder_z_.data != nullptr;
	// forEachInView's walk without the sight tests: in view, inside the image, not occluded
	const auto walk = [&](const std::vector<EdgeSample>& samples, size_t offset)
	{
		const auto each = [&](const ProjectedRun& r, size_t first, size_t n)
		{
			const auto base = static_cast<std::uint32_t>(offset + first);
			for (size_t j = 0; j < n; ++j)
			{
				const double u = r.u[j], v = r.v[j];
				if (!r.in_view[j] || !(u >= 0 && u < max_u && v >= 0 && v < max_v)) continue;
				const Pixel at = pixelOf(cv::Point2d(u, v));
				if (occluders && occludedAt(at, r.z[j])) continue;
				const auto k = base + static_cast<std::uint32_t>(j);
				// the distance first: most samples of a yaw that fits badly are far from edges
				if (reach[at.y * reach_step + at.x] == kClose &&
				    oriented(at, cv::Point2d(r.tu[j], r.tv[j])))
					on[n_on++] = k;
				else
					off[n_off++] = k;
			}
			return true;
		};
		forEachRun(ss, samples, T_OinC, each);
	};
	walk(ss.samples_O, 0);
	walk(limbs, ss.samples_O.size());
	out.on_edge.resize(n_on), out.off_edge.resize(n_off);
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
	// the fraction's bound holds for a fraction of at most 1 (YawBound)
	if (!(max_score <= 1)) return scoreUnlessExceeded(samples, T_OinL, cap);
	static thread_local YawBound::Limbs limbs;
	static thread_local YawBound::Both prospects;
	for (size_t i = 0; i < 2; ++i)
	{
		images_[i].limbsSeen(samples, T_OinL, limbs[i]);
		images_[i].prospects(samples, T_OinL, limbs[i], prospects[i]);
	}
	const auto viewOf = [&](size_t i)
	{
		return samples.occ ? samples.occ->viewFrom(T_OinL.inverse() * images_[i].centre_L())
		                   : SelfOcclusion::View();
	};
	const YawBound::Views views{viewOf(0), viewOf(1)};
	YawBound bound(images_, samples, limbs, prospects, views);
	if (!bound.countRuledOut(min_supported)) return score(samples, T_OinL);
	if (bound.fractionRuledOut(max_score)) return std::nullopt;
	// every sight tested: the complete counts, decided as ScoreCap decides them
	cap.supported = bound.supportedMax(), cap.considered = bound.consideredMin();
	if (cap.exceeded()) return std::nullopt;
	return score(samples, T_OinL);
}

}  // namespace mrolr::recog
