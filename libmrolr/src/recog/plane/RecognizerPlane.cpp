// Recognizer's second source of hypotheses: single scene features on the support plane
// (PlaneHypotheses.h), ranked by a quick image score and judged in the images like the clique
// hypotheses (judgeInImages). Only with images: a hypothesis shares a single feature with the
// scene, so its 3D score says next to nothing about it; the images see the whole object.
#include "../RecognizerDetail.h"

#include <mrolr/recog/CliqueMatcher.h>
#include <mrolr/recog/Recognizer.h>

#include <algorithm>
#include <cmath>

namespace mrolr::recog
{
namespace
{
constexpr double kSamePose_mm = 5, kSamePose_deg = 5;  // near-duplicate hypotheses

bool samePose(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b, const Eigen::Vector3d& c_O)
{
	return detail::nearPose(a, b, c_O, kSamePose_mm, kSamePose_deg);
}

/** Indices of @p score sorted best first, near-duplicates of a better one dropped, at most @p n. */
std::vector<size_t> bestDistinct(const std::vector<PlaneHypothesis>& hyps,
                                 const std::vector<double>& score, const Eigen::Vector3d& c_O,
                                 size_t n)
{
	std::vector<size_t> order(hyps.size());
	for (size_t k = 0; k < order.size(); ++k) order[k] = k;
	std::sort(order.begin(), order.end(), [&](size_t a, size_t b) { return score[a] > score[b]; });
	std::vector<size_t> kept;
	for (const size_t k : order)
	{
		if (kept.size() >= n) break;
		const bool dup =
		    std::any_of(kept.begin(), kept.end(),
		                [&](size_t j) { return samePose(hyps[j].T_OinS, hyps[k].T_OinS, c_O); });
		if (!dup) kept.push_back(k);
	}
	return kept;
}
}  // namespace

RecognitionResult Recognizer::recognizeOnPlane(const std::vector<Feature>& scene,
                                               const SupportPlane& plane,
                                               const ImageVerifier& images) const
{
	Refinements refined;
	return onPlane(scene, plane, images, refined);
}

RecognitionResult Recognizer::onPlane(const std::vector<Feature>& scene, const SupportPlane& plane,
                                      const ImageVerifier& images, Refinements& refined) const
{
	const PlaneHypothesisOptions& po = opts_.plane;
	RecognitionResult best;
	best.model = table_.name();
	best.image_score = 0;
	std::vector<PlaneHypothesis> hyps;
	std::vector<double> quick;
	{
		const detail::StageTimer timer(best.times.plane_ms);
		hyps = plane_gen_->generate(scene, plane);
		const SightedSamples& coarse = sightedSamples(po.prerank_spacing_mm);
		// the score alone: the cost is not asked
		for (const auto& h : hyps) quick.push_back(images.score(coarse, h.T_OinS, false).score);
	}
	const Eigen::Vector3d* up_S = &plane.n_S;
	const LevelParams& p = opts_.levels.back();
	const OrientedScene os = orientScene(scene, p.length_threshold_mm);
	const double beta = detail::verifyBeta_mm(p, opts_), theta = detail::verifyTheta_rad(p, opts_);
	std::vector<VerifiedPose> poses;
	{
		const detail::StageTimer timer(best.times.verify_3d_ms);
		for (const size_t k :
		     bestDistinct(hyps, quick, centroid_O_, static_cast<size_t>(po.max_hypotheses)))
		{
			const Eigen::Isometry3d& T = hyps[k].T_OinS;
			poses.push_back({T,
			                 verifyPose(table_, os.features, T, beta, theta, p.length_threshold_mm,
			                            occlusionFor(up_S)),
			                 std::nullopt,
			                 k,
			                 {}});
		}
	}
	judgeInImages(poses, images, os.features, p, up_S, refined, best.times);
	double best_rank = -1;
	std::vector<VerifiedPose> eligible;  // the poses that could be the answer
	for (const auto& h : poses)
	{
		const double rank = detail::rankOf(h.v, h.image);
		// a pair of vertical lines is common in a scene of boxes and cylinders: edge-pair answers
		// need more of the images
		if (hyps[h.hypothesis].from_edge_pair && *h.image < po.edge_pair_min_image_score) continue;
		if (!upright(h.T, up_S) ||
		    std::abs(plane_gen_->baseOffset_mm(h.T, plane)) > po.max_base_offset_mm)
			continue;
		eligible.push_back(h);
		if (rank <= best_rank) continue;
		best_rank = rank;
		best.image_score = h.image;
		best.T_OinS = h.T;
		best.score = h.v.score;
		best.coverage = h.v.coverage;
		best.matched = h.v.matched;
		best.agreeing_cliques = 0;
		best.origin = Origin::SupportPlane;
	}
	best.found = *best.image_score >= std::max(images.options().min_score, po.min_image_score);
	if (!best.found) return best;
	best.confidence = planeConfidence(*best.image_score);
	markAmbiguity(best, eligible);
	return best;
}

}  // namespace mrolr::recog
