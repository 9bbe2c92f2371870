// Refinement of a pose hypothesis in the stereo images (ImageVerifier::refine): a sweep of
// rotations about the model's up axis, then Levenberg–Marquardt on the samples' distances to the
// edge lines (ImageEdgeLines.cpp). Both move the pose only where the images say it fits better.
#include <mrolr/recog/images/ImageVerifier.h>
#include <mrolr/recog/images/RefineMemo.h>

#include <cmath>

namespace mrolr::recog
{
namespace
{
/** Two starts have the same circle of yaws about an axis (RefineMemo) when their axis points lie
 * within kSameCircle_mm, their up axes within kSameCircle_deg, and their yaws differ by a whole
 * number of sweep steps to within kSameCircle_deg. 0.1 mm is 0.1 px at 650 mm. Measured on the
 * eight rendered sets (seeds 1 to 701): at 0.1 every count and median stays or improves; at 0.2,
 * which takes 34 circles on the bench sweep instead of 19, the counts stay but seeds 101's and
 * 401's medians rise (0.337° → 0.357°, 0.497 → 0.552 mm); at 2 (the kSameStart of
 * RecognizerImages.cpp), seeds 1, 101 and 701 each lose a view. */
constexpr double kSameCircle_mm = 0.1, kSameCircle_deg = 0.1;

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

bool sameCircle(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b, const Eigen::Vector3d& a_O,
                double step_deg)
{
	const double cos_up = a.linear().col(2).dot(b.linear().col(2));
	if ((a * a_O - b * a_O).norm() >= kSameCircle_mm ||
	    cos_up <= std::cos(kSameCircle_deg * M_PI / 180))
		return false;
	const Eigen::Matrix3d D = a.linear().transpose() * b.linear();  // about O's z, nearly
	const double turns = std::atan2(D(1, 0), D(0, 0)) * 180 / M_PI / step_deg;
	return std::abs(turns - std::round(turns)) * step_deg < kSameCircle_deg;
}

/** A seed of the local search: a pose, its score and the axis it turns about. */
struct Seed
{
	ScoredPose p;
	Eigen::Vector3d axis_O;
};
}  // namespace

Eigen::Isometry3d ImageVerifier::refine(const std::vector<EdgeSample>& samples_O,
                                        const Eigen::Isometry3d& T_OinL, const SelfOcclusion* occ,
                                        const std::vector<Eigen::Vector3d>& axes_O) const
{
	return refine(SightedSamples(samples_O, occ), T_OinL, axes_O);
}

SweptCircle ImageVerifier::sweptAbout(const SightedSamples& samples, const ScoredPose& start,
                                      const Eigen::Vector3d& a_O) const
{
	SweptCircle c{start, start};
	const double yaw_step = opts_.yaw_step_deg * M_PI / 180;
	for (double yaw = yaw_step; yaw_step > 0 && yaw < 2 * M_PI - 1e-9; yaw += yaw_step)
	{
		const Eigen::Isometry3d T = start.T * aboutAxis(a_O, yaw);
		// only a yaw that may beat one of them is counted to the end (scoreIfMore)
		const auto s = scoreIfMore(samples, T, c.by_count.s.supported, c.by_fraction.s.score);
		if (!s) continue;
		if (better(*s, c.by_count.s)) c.by_count = {T, *s};
		if (s->score > c.by_fraction.s.score) c.by_fraction = {T, *s};
	}
	return c;
}

SweptCircle ImageVerifier::circleOf(const SightedSamples& samples, const ScoredPose& start,
                                    const std::vector<Eigen::Vector3d>& axes_O, size_t k,
                                    RefineMemo* memo) const
{
	if (memo)
		for (const auto& c : memo->circles)
			if (c.axis == k && sameCircle(c.T, start.T, axes_O[k], opts_.yaw_step_deg))
			{
				++memo->circles_reused;
				return c.swept;
			}
	const SweptCircle swept = sweptAbout(samples, start, axes_O[k]);
	if (memo) memo->circles.push_back({k, start.T, swept});
	return swept;
}

ScoredPose ImageVerifier::searchedFrom(const SightedSamples& samples, const ScoredPose& seed,
                                       const Eigen::Vector3d& axis_O, RefineMemo* memo) const
{
	if (memo)
		for (const auto& s : memo->searches)
			if (s.axis_O == axis_O && s.seed.isApprox(seed.T)) return s.result;
	const ScoredPose r = edgeLineSearch(samples, seed, axis_O);
	if (memo) memo->searches.push_back({seed.T, axis_O, r});
	return r;
}

Eigen::Isometry3d ImageVerifier::refine(const SightedSamples& samples,
                                        const Eigen::Isometry3d& T_OinL,
                                        const std::vector<Eigen::Vector3d>& axes_O,
                                        RefineMemo* memo) const
{
	return refine(samples, ScoredPose{T_OinL, score(samples, T_OinL)}, axes_O, memo).T;
}

ScoredPose ImageVerifier::refine(const SightedSamples& samples, const ScoredPose& start_pose,
                                 const std::vector<Eigen::Vector3d>& axes_O, RefineMemo* memo) const
{
	// the sweep keeps the yaw with the most supported samples and the one with the highest
	// fraction; each is scored unrefined, so both (and the start) are refined and compared then
	const Eigen::Vector3d axis0_O = axes_O.empty() ? Eigen::Vector3d::Zero() : axes_O.front();
	const Seed start{start_pose, axis0_O};
	Seed by_count = start, by_fraction = start;
	for (size_t k = 0; k < axes_O.size(); ++k)
	{
		const SweptCircle c = circleOf(samples, start.p, axes_O, k, memo);
		if (better(c.by_count.s, by_count.p.s)) by_count = {c.by_count, axes_O[k]};
		if (c.by_fraction.s.score > by_fraction.p.s.score) by_fraction = {c.by_fraction, axes_O[k]};
	}
	ScoredPose best = searchedFrom(samples, by_count.p, by_count.axis_O, memo);
	std::vector<const Seed*> others;  // each distinct seed refined once
	if (!start.p.T.isApprox(by_count.p.T)) others.push_back(&start);
	if (!by_fraction.p.T.isApprox(by_count.p.T) && !by_fraction.p.T.isApprox(start.p.T))
		others.push_back(&by_fraction);
	for (const Seed* o : others)
	{
		const ScoredPose r = searchedFrom(samples, o->p, o->axis_O, memo);
		if (better(r.s, best.s)) best = r;
	}
	return best.s.supported >= by_count.p.s.supported ? best : by_count.p;
}

}  // namespace mrolr::recog
