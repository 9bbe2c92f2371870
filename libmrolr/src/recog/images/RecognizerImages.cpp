// Recognizer's verification in the stereo images (ImageVerifier.h): every pose that passed the 3D
// pre-filter is scored in the images; the best few are refined there and verified again in 3D.
#include "../RecognizerDetail.h"

#include <mrolr/recog/Recognizer.h>

#include <algorithm>

namespace mrolr::recog
{
void Recognizer::judgeInImages(std::vector<VerifiedPose>& poses, const ImageVerifier& images,
                               const std::vector<Feature>& scene, const LevelParams& p,
                               const Eigen::Vector3d* up_S, RecognitionTimes& times) const
{
	const auto& o = images.options();
	const SightedSamples& samples = sightedSamples(o.sample_spacing_mm);
	{
		const detail::StageTimer timer(times.image_score_ms);
		for (auto& h : poses) h.image = images.score(samples, h.T).score;
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
		const Eigen::Isometry3d T = images.refine(samples, h.T, axes_O);
		if (!upright(T, up_S)) continue;
		h.T = T;
		h.image = images.score(samples, T).score;
		h.v = verifyPose(table_, scene, T, beta, theta, p.length_threshold_mm, occlusionFor(up_S));
	}
}

}  // namespace mrolr::recog
