// Scores that give up early (ScoreCap): the refinement's local search and yaw sweep want a
// pose's score only when the pose can beat the best one; the count stops as soon as the samples
// counted prove that it cannot, and the answer is otherwise score() itself.
#include <mrolr/recog/images/ImageVerifier.h>

namespace mrolr::recog
{
std::optional<ImageScore> ImageVerifier::scoreIfCheaper(const SightedSamples& samples,
                                                        const Eigen::Isometry3d& T_OinL,
                                                        double max_cost_px2) const
{
	return scoreIfCheaper(samples, T_OinL, max_cost_px2, nullptr);
}

std::optional<ImageScore> ImageVerifier::scoreIfCheaper(const SightedSamples& samples,
                                                        const Eigen::Isometry3d& T_OinL,
                                                        double max_cost_px2,
                                                        AlignedPair* aligned) const
{
	ScoreCap cap;
	cap.max_mean_px2 = max_cost_px2;
	const auto s = scoreUnlessExceeded(samples, T_OinL, cap, aligned);
	if (!s || s->cost >= max_cost_px2) return std::nullopt;
	return s;
}

std::optional<ImageScore> ImageVerifier::scoreUnlessExceeded(const SightedSamples& samples,
                                                             const Eigen::Isometry3d& T_OinL,
                                                             ScoreCap cap,
                                                             AlignedPair* aligned) const
{
	// the sweep and the local search ask at every pose: the limbs' storage is kept per thread
	static thread_local std::array<std::vector<EdgeSample>, 2> limbs;
	for (size_t i = 0; i < images_.size(); ++i)
	{
		images_[i].limbsSeen(samples, T_OinL, limbs[i]);
		cap.unvisited += static_cast<int>(samples.samples_O.size() + limbs[i].size());
	}
	std::array<ImageCount, 2> counts;
	for (size_t i = 0; i < images_.size(); ++i)
	{
		const auto c = images_[i].count(samples, T_OinL, limbs[i], opts_.truncate_px, &cap,
		                                aligned ? &(*aligned)[i] : nullptr);
		if (!c) return std::nullopt;
		counts[i] = *c;
	}
	return combined(counts);
}

}  // namespace mrolr::recog
