// Recognizer's verification in the stereo images (ImageVerifier.h): every pose that passed the 3D
// pre-filter is scored in the images; the best few are refined there and verified again in 3D.
#include "../RecognizerDetail.h"

#include <mrolr/recog/Recognizer.h>

#include <algorithm>

namespace mrolr::recog
{
namespace
{
/** A pose this near the start or the result of a refinement already made in the same search is
 * not refined again (the move of the model's centroid, and the angle): the refinement sweeps every
 * yaw and its local search reaches kRefinementReach (25 mm, 35°), so from there it lands where
 * that one did. On the rendered sets of seeds 1, 101, 201 and 601 this spares 12–27 % of the
 * refinements; the recognised, false-positive and wrong-pose counts of the eight sets (seeds 1 to
 * 701) stay the same. At 5 mm and 5° it spares 22–34 %, but seed 301 loses a recognition. */
constexpr double kSameStart_mm = 2, kSameStart_deg = 2;

bool sameStart(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b, const Eigen::Vector3d& c_O)
{
	return detail::nearPose(a, b, c_O, kSameStart_mm, kSameStart_deg);
}
}  // namespace

ScoredPose Recognizer::refinedOnce(const ImageVerifier& images, const SightedSamples& samples,
                                   const ScoredPose& start,
                                   const std::vector<Eigen::Vector3d>& axes_O,
                                   Refinements& refined) const
{
	for (const auto& m : refined.made)
		if (sameStart(m.start, start.T, centroid_O_) || sameStart(m.result.T, start.T, centroid_O_))
		{
			++refined.reused;
			return m.result;
		}
	const ScoredPose r = images.refine(samples, start, axes_O, &refined.memo);
	refined.made.push_back({start.T, r});
	return r;
}

void Recognizer::judgeInImages(std::vector<VerifiedPose>& poses, const ImageVerifier& images,
                               const std::vector<Feature>& scene, const LevelParams& p,
                               const Eigen::Vector3d* up_S, Refinements& refined,
                               RecognitionTimes& times) const
{
	const auto& o = images.options();
	const SightedSamples& samples = sightedSamples(o.sample_spacing_mm);
	{
		const detail::StageTimer timer(times.image_score_ms);
		for (auto& h : poses)
			h.image_counts = images.score(samples, h.T), h.image = h.image_counts.score;
	}
	std::sort(poses.begin(), poses.end(),
	          [](const VerifiedPose& a, const VerifiedPose& b) { return a.image > b.image; });
	const std::vector<Eigen::Vector3d> axes_O = upAxisPoints(table_.features());
	const double beta = detail::verifyBeta_mm(p, opts_), theta = detail::verifyTheta_rad(p, opts_);
	const detail::StageTimer timer(times.image_refine_ms);
	for (size_t k = 0; k < poses.size() && static_cast<int>(k) < o.refine_candidates; ++k)
	{
		auto& h = poses[k];
		if (*h.image < 0.5 * o.min_score) break;
		const ScoredPose r = refinedOnce(images, samples, {h.T, h.image_counts}, axes_O, refined);
		if (!upright(r.T, up_S)) continue;
		h.T = r.T, h.image_counts = r.s, h.image = r.s.score;
		h.v =
		    verifyPose(table_, scene, r.T, beta, theta, p.length_threshold_mm, occlusionFor(up_S));
	}
}

}  // namespace mrolr::recog
