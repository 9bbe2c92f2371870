// Refinement of a pose hypothesis in the stereo images (ImageVerifier::refine): a sweep of
// rotations about the model's up axis, then Levenberg–Marquardt on the samples' distances to the
// edge lines (ImageEdgeLines.cpp). Both move the pose only where the images say it fits better.
#include <mrolr/recog/images/ImageVerifier.h>

#include <cmath>

namespace mrolr::recog
{
namespace
{
Eigen::Isometry3d aboutAxis(const Eigen::Vector3d& a_O, double yaw_rad)
{
	return Eigen::Translation3d(a_O) * Eigen::AngleAxisd(yaw_rad, Eigen::Vector3d::UnitZ()) *
	       Eigen::Translation3d(-a_O);
}

/** The yaw sweep prefers more supported samples, not a higher fraction: turned so that a cup's
 * handle is hidden behind it, the rims alone are all supported (a high fraction); turned so that
 * the handle shows and is supported, more samples are. */
bool better(const ImageScore& a, const ImageScore& b)
{
	return a.supported > b.supported || (a.supported == b.supported && a.cost < b.cost);
}
}  // namespace

Eigen::Isometry3d ImageVerifier::refine(const std::vector<EdgeSample>& samples_O,
                                        const Eigen::Isometry3d& T_OinL, const SelfOcclusion* occ,
                                        const std::vector<Eigen::Vector3d>& axes_O) const
{
	return refine(SightedSamples(samples_O, occ), T_OinL, axes_O);
}

Eigen::Isometry3d ImageVerifier::refine(const SightedSamples& samples,
                                        const Eigen::Isometry3d& T_OinL,
                                        const std::vector<Eigen::Vector3d>& axes_O) const
{
	// the sweep keeps the yaw with the most supported samples and the one with the highest
	// fraction; each is scored unrefined, so both (and the start) are refined and compared then
	struct Seed
	{
		Eigen::Isometry3d T;
		ImageScore s;
		Eigen::Vector3d axis_O;
	};
	const Eigen::Vector3d axis0_O = axes_O.empty() ? Eigen::Vector3d::Zero() : axes_O.front();
	const Seed start{T_OinL, score(samples, T_OinL), axis0_O};
	Seed by_count = start, by_fraction = start;
	const double yaw_step = opts_.yaw_step_deg * M_PI / 180;
	for (const auto& a_O : axes_O)
		for (double yaw = yaw_step; yaw_step > 0 && yaw < 2 * M_PI - 1e-9; yaw += yaw_step)
		{
			const Eigen::Isometry3d T = T_OinL * aboutAxis(a_O, yaw);
			// only a yaw that may beat one of them is counted to the end (scoreIfMore)
			const auto s =
			    scoreIfMore(samples, T, by_count.s.supported, by_fraction.s.score);
			if (!s) continue;
			if (better(*s, by_count.s)) by_count = {T, *s, a_O};
			if (s->score > by_fraction.s.score) by_fraction = {T, *s, a_O};
		}
	auto [best, best_s] = edgeLineSearch(samples, by_count.T, by_count.s, by_count.axis_O);
	std::vector<const Seed*> others;  // each distinct seed refined once
	if (!start.T.isApprox(by_count.T)) others.push_back(&start);
	if (!by_fraction.T.isApprox(by_count.T) && !by_fraction.T.isApprox(start.T))
		others.push_back(&by_fraction);
	for (const Seed* o : others)
	{
		const auto [T, s] = edgeLineSearch(samples, o->T, o->s, o->axis_O);
		if (better(s, best_s)) best = T, best_s = s;
	}
	return best_s.supported >= by_count.s.supported ? best : by_count.T;
}

}  // namespace mrolr::recog
