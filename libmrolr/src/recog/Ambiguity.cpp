// Ambiguous answers: rival poses supported about as well as the best, that no symmetry of the
// model explains (beyond the thesis; docs/recog.md).
#include "RecognizerDetail.h"

#include <mrolr/recog/Recognizer.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace mrolr::recog
{
namespace
{
double turnDeg(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b)
{
	return Eigen::AngleAxisd(a.linear().transpose() * b.linear()).angle() * 180.0 / M_PI;
}
}  // namespace

bool Recognizer::symmetric(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b) const
{
	// a symmetry maps nearly all of the model onto itself: a can's rims under a turn about its
	// axis, though not the few printed lines a turntable model of it may carry
	const auto samples = edgeSamples(5.0);
	const double tol2 = opts_.ambiguity_symmetry_mm * opts_.ambiguity_symmetry_mm;
	size_t kept = 0;
	for (const auto& s : samples)
	{
		const Eigen::Vector3d p = b * s.p_O;
		double nearest = std::numeric_limits<double>::infinity();
		for (const auto& q : samples) nearest = std::min(nearest, (a * q.p_O - p).squaredNorm());
		if (nearest <= tol2) ++kept;
	}
	return !samples.empty() && kept >= opts_.ambiguity_symmetry_share * samples.size();
}

void Recognizer::markAmbiguity(RecognitionResult& best, const std::vector<VerifiedPose>& poses) const
{
	double best_rank = 0;  // the answer is the best-ranked of the poses
	for (const auto& h : poses) best_rank = std::max(best_rank, detail::rankOf(h.v, h.image));
	std::vector<PoseSupport> rivals{{best.T_OinS, best_rank}};
	for (const auto& h : poses)
	{
		const double rank = detail::rankOf(h.v, h.image);
		if (rank < (1.0 - opts_.ambiguity_margin) * best_rank) continue;
		bool distinct = true;
		for (const auto& r : rivals)
			distinct = distinct && turnDeg(r.T_OinS, h.T) >= opts_.ambiguity_min_turn_deg;
		if (distinct && !symmetric(best.T_OinS, h.T)) rivals.push_back({h.T, rank});
	}
	best.ambiguous = rivals.size() > 1;
	if (best.ambiguous) best.poses = std::move(rivals);
}

}  // namespace mrolr::recog
