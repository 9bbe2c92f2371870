#include <mrolr/eval/RecognitionEvaluation.h>
#include <mrolr/recog/Verification.h>

#include <algorithm>

namespace mrolr::eval
{
namespace
{
double median(std::vector<double> v)
{
	if (v.empty()) return -1;
	std::sort(v.begin(), v.end());
	const size_t n = v.size();
	return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

/** Score of the model at its true pose: how much of it the scene could support at best. */
double truthScore(const recog::Recognizer& rec, const std::vector<recog::Feature>& scene,
                  const Eigen::Isometry3d& T_OinL, const Eigen::Vector3d& up_L)
{
	const auto& o = rec.options();
	return recog::verifyPose(rec.table(), scene, T_OinL, o.verify_position_error_mm,
	                         o.verify_rotation_deg * M_PI / 180,
	                         o.levels.front().length_threshold_mm, rec.occlusion(up_L))
	    .score;
}
}  // namespace

EvalCase evaluateCase(const recog::Recognizer& rec, const EvalScene& s,
                      const std::vector<double>& symmetry_deg, const EvaluationOptions& opts,
                      const recog::SceneContext& context)
{
	EvalCase c;
	c.scene = s.index;
	c.model = rec.table().name();
	const auto scene = recog::featuresOf(s.scene);
	recog::SceneContext with_up = context;
	with_up.up_S = s.up_L;
	const recog::RecognitionResult r = rec.recognize(scene, with_up);
	c.result = r;
	c.image_score = r.image_score;
	c.found = r.found, c.score = r.score, c.level = r.level, c.ms = r.ms;
	c.levels_skipped = r.levels_skipped;
	c.score_bound =
	    rec.supportBound_mm(scene) / rec.modelLength_mm(rec.options().levels.size() - 1);
	const EvalObject* truth = s.find(c.model);
	c.present = truth != nullptr;
	if (!truth) return c;
	c.visible_fraction = truth->visible_fraction;
	c.truth_score = truthScore(rec, scene, truth->T_OinL, s.up_L);
	if (context.images)
	{
		const recog::ImageVerifier& images = *context.images;
		c.truth_image_score = images
		                          .score(rec.edgeSamples(images.options().sample_spacing_mm),
		                                 truth->T_OinL, &rec.selfOcclusion())
		                          .score;
	}
	if (!c.found) return c;
	c.rot_err_deg = rotationErrorDeg(truth->T_OinL.linear(), r.T_OinS.linear(), symmetry_deg);
	c.trans_err_mm = (truth->T_OinL.translation() - r.T_OinS.translation()).norm();
	c.correct = c.rot_err_deg <= opts.max_rotation_error_deg &&
	            c.trans_err_mm <= opts.max_translation_error_mm;
	return c;
}

EvalSummary summarize(const std::vector<EvalCase>& cases, const EvaluationOptions& opts)
{
	EvalSummary s;
	std::vector<double> rot, trans, ms, absent_ms;
	for (const auto& c : cases)
	{
		ms.push_back(c.ms);
		s.mean_times += c.result.times;
		s.max_ms = std::max(s.max_ms, c.ms);
		if (!c.present)
		{
			++s.absent_cases, absent_ms.push_back(c.ms);
			s.false_positives += c.found ? 1 : 0;
			continue;
		}
		s.wrong_poses += c.found && !c.correct ? 1 : 0;
		if (c.visible_fraction < opts.min_visible_fraction) continue;
		++s.rate_cases;
		if (!c.correct) continue;
		s.recognised_from_plane += c.result.origin == recog::Origin::SupportPlane ? 1 : 0;
		++s.recognised, rot.push_back(c.rot_err_deg), trans.push_back(c.trans_err_mm);
	}
	s.rate = s.rate_cases ? static_cast<double>(s.recognised) / s.rate_cases : 0;
	s.median_rot_err_deg = median(rot), s.median_trans_err_mm = median(trans);
	s.median_ms = median(ms), s.median_absent_ms = median(absent_ms);
	if (!cases.empty()) s.mean_times = s.mean_times.scaled(1.0 / static_cast<double>(cases.size()));
	return s;
}

}  // namespace mrolr::eval
