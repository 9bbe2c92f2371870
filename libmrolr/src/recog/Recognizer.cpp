#include "RecognizerDetail.h"

#include <mrolr/recog/CliqueMatcher.h>
#include <mrolr/recog/PoseEstimation.h>
#include <mrolr/recog/Recognizer.h>
#include <mrolr/recog/SupportBound.h>
#include <mrolr/recog/TransformCluster.h>
#include <mrolr/recog/Verification.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <memory>
#include <stdexcept>

namespace mrolr::recog
{
using detail::rankOf;
using detail::StageTimer;
using detail::verifyAndRefine;
using detail::verifyBeta_mm;
using detail::verifyTheta_rad;

namespace
{
constexpr size_t kMatchesPerClique = 20;  // strongest clique matches kept as hypotheses

std::vector<Correspondence> correspondencesOf(const ModelTable& model, const OrientedScene& scene,
                                              const CliqueMatch& cm)
{
	std::vector<Correspondence> cs;
	cs.reserve(cm.matches.size());
	for (const auto& m : cm.matches)
		cs.push_back({model.features()[m.model], scene.oriented[m.oriented]});
	return cs;
}

void addPoses(const std::vector<Correspondence>& cs, const RecognitionOptions& o,
              const LevelParams& p, double weight, std::vector<PoseHypothesis>& out)
{
	if (o.pose_method != PoseMethod::Arun)
		if (auto T = faugerasHebertPose(cs)) out.push_back({*T, weight});
	if (o.pose_method != PoseMethod::FaugerasHebert)
		if (auto T = arunPose(cs, 2 * p.position_error_mm)) out.push_back({*T, weight});
}

std::vector<PoseHypothesis> hypothesesAt(const ModelTable& model, const OrientedScene& scene,
                                         const RecognitionOptions& o, const LevelParams& p,
                                         const FocusFilter& focus_ok, MemberCandidates* members)
{
	std::vector<PoseHypothesis> hyps;
	for (size_t c = 0; c < model.cliques().size(); ++c)
	{
		const auto matches = matchClique(model, c, scene, p, o.max_search_nodes, focus_ok, members);
		for (size_t k = 0; k < matches.size() && k < kMatchesPerClique; ++k)
			addPoses(correspondencesOf(model, scene, matches[k]), o, p,
			         static_cast<double>(matches[k].matches.size()), hyps);
	}
	return hyps;
}

}  // namespace

std::pair<Eigen::Isometry3d, VerificationResult> detail::verifyAndRefine(
    const ModelTable& model, const std::vector<Feature>& scene, Eigen::Isometry3d T,
    const LevelParams& p, const RecognitionOptions& o, const SelfOcclusion* occ)
{
	const double beta = verifyBeta_mm(p, o), theta = verifyTheta_rad(p, o);
	const int iterations = o.refine_iterations;
	VerificationResult v = verifyPose(model, scene, T, beta, theta, p.length_threshold_mm, occ);
	for (int i = 0; i < iterations; ++i)
	{
		const auto T2 = faugerasHebertPose(v.correspondences);
		if (!T2) break;
		VerificationResult v2 =
		    verifyPose(model, scene, *T2, beta, theta, p.length_threshold_mm, occ);
		if (rankOf(v2) < rankOf(v)) break;
		T = *T2;
		v = std::move(v2);
	}
	return {T, std::move(v)};
}

namespace
{
double rankOf(const RecognitionResult& r)
{
	return r.image_score ? *r.image_score + 0.05 * r.score : r.score + 0.05 * r.coverage;
}

/** Smallest expected-visible share of the model's length over cameras 300 mm from the centroid
 * in 200 directions, less 20 % for nearer or in-between viewpoints. */
double minVisibleShare(const std::vector<Feature>& fs, const SelfOcclusion& occ,
                       const Eigen::Vector3d& centroid_O)
{
	double total = 0, least = 1;
	for (const auto& f : fs) total += f.len_mm;
	for (const auto& d : sphereDirections(200))
	{
		const auto seen = occ.visibleFractions(centroid_O + 300 * d);
		double vis = 0;
		for (size_t k = 0; k < fs.size(); ++k) vis += seen[k] * fs[k].len_mm;
		least = std::min(least, total > 0 ? vis / total : 1.0);
	}
	return 0.8 * least;
}

}  // namespace

double cliqueConfidence(double score, int level, size_t levels)
{
	const double f = levels > 1 ? static_cast<double>(level - 1) / (levels - 1) : 0.0;
	return score * (1.0 - 0.5 * f);
}

const char* originName(Origin origin)
{
	switch (origin)
	{
		case Origin::Clique: return "clique";
		case Origin::SupportPlane: return "support_plane";
		case Origin::None: break;
	}
	return "none";
}

double planeConfidence(double image_score)
{
	return 0.5 * image_score;
}

std::optional<Eigen::Vector3d> SceneContext::up() const
{
	if (up_S) return up_S;
	if (plane) return plane->n_S;
	return std::nullopt;
}

Recognizer::Recognizer(const model::WireFrame& model, const RecognitionOptions& opts)
    : table_(model, opts.auto_clique_count, opts.auto_clique_size, opts.auto_cliques,
             opts.file_cliques),
      model_(model),
      opts_(opts)
{
	if (opts_.levels.empty()) throw std::invalid_argument("recognition options have no levels");
	if (opts_.file_cliques_with_images != opts_.file_cliques)
		image_table_ =
		    std::make_shared<ModelTable>(model, opts.auto_clique_count, opts.auto_clique_size,
		                                 opts.auto_cliques, opts.file_cliques_with_images);
	centroid_O_.setZero();
	for (const auto& f : table_.features()) centroid_O_ += f.m;
	centroid_O_ /= static_cast<double>(table_.features().size());
	occlusion_ = std::make_shared<SelfOcclusion>(table_.features());
	samples_ = newSampleCache();
	levels_cache_ = newLevelCache();
	plane_gen_ = std::make_shared<PlaneHypothesisGenerator>(table_.features(), modelBaseZ_mm(model),
	                                                        opts_.plane);
	if (!opts_.verify_visible_only) return;
	min_visible_share_ = minVisibleShare(table_.features(), *occlusion_, centroid_O_);
}

const SelfOcclusion* Recognizer::occlusionFor(const Eigen::Vector3d* up_S) const
{
	return up_S && opts_.upright_max_tilt_deg < 180 && opts_.verify_visible_only ? occlusion_.get()
	                                                                             : nullptr;
}

double Recognizer::visibleShare(const Eigen::Vector3d* up_S) const
{
	return occlusionFor(up_S) ? min_visible_share_ : 1.0;
}

double Recognizer::minScore(size_t level, const Eigen::Vector3d* up_S,
                            const ImageVerifier* images) const
{
	if (images) return images->options().prefilter_score;
	const double f = occlusionFor(up_S) ? opts_.visible_min_score_factor : 1.0;
	return std::min(1.0, f * opts_.levels.at(level).verify_min_score);
}

bool Recognizer::upright(const Eigen::Isometry3d& T_OinS, const Eigen::Vector3d* up_S) const
{
	if (!up_S || opts_.upright_max_tilt_deg >= 180) return true;
	const double c = (T_OinS.linear() * Eigen::Vector3d::UnitZ()).dot(up_S->normalized());
	return c >= std::cos(opts_.upright_max_tilt_deg * M_PI / 180);
}

RecognitionResult Recognizer::recognizeAtLevel(const std::vector<Feature>& scene, size_t level,
                                               FocusBounds& bounds,
                                               const SceneContext& context) const
{
	const auto up = context.up();
	Refinements refined;
	return atLevel(scene, level, bounds, up ? &*up : nullptr,
	               context.images ? &context.images->get() : nullptr, context.repeat, refined);
}

RecognitionResult Recognizer::atLevel(const std::vector<Feature>& scene, size_t level,
                                      FocusBounds& bounds, const Eigen::Vector3d* up_S,
                                      const ImageVerifier* images, bool repeat,
                                      Refinements& refined) const
{
	const LevelParams& p = opts_.levels.at(level);
	RecognitionResult best;
	best.model = table_.name();
	if (images) best.image_score = 0.0;
	const OrientedScene os = orientScene(scene, p.length_threshold_mm);
	auto [clusters, verified] =
	    levelHypotheses(scene, os, level, bounds, up_S, images, repeat, best.times);
	if (images) judgeInImages(verified, *images, os.features, p, up_S, refined, best.times);
	double best_rank = 0;
	for (const auto& h : verified)
	{
		if (rankOf(h.v, h.image) <= best_rank) continue;
		best_rank = rankOf(h.v, h.image);
		best.image_score = h.image;
		best.T_OinS = h.T;
		best.score = h.v.score;
		best.coverage = h.v.coverage;
		best.matched = h.v.matched;
		best.origin = Origin::Clique;
		best.agreeing_cliques = static_cast<int>(clusters[h.hypothesis].members.size());
		best.spread_rot_deg = clusters[h.hypothesis].spread_rot_deg;
		best.spread_trans_mm = clusters[h.hypothesis].spread_trans_mm;
	}
	best.found = images ? *best.image_score >= images->options().min_score
	                    : best.score >= minScore(level, up_S);
	if (!best.found) return best;
	markAmbiguity(best, verified);
	best.level = static_cast<int>(level) + 1;
	best.confidence = cliqueConfidence(images ? std::max(0.0, *best.image_score) : best.score,
	                                   *best.level, opts_.levels.size());
	return best;
}

Recognizer::LevelHypotheses Recognizer::computeLevelHypotheses(
    const std::vector<Feature>& scene, const OrientedScene& os, size_t level, FocusBounds& bounds,
    const Eigen::Vector3d* up_S, const ImageVerifier* images, RecognitionTimes& times) const
{
	const LevelParams& p = opts_.levels.at(level);
	LevelHypotheses out;
	{
		const StageTimer timer(times.cliques_ms);
		const ModelTable& table = tableFor(images != nullptr);
		// with images every level runs (the 3D score only pre-filters): the members' candidates
		// are shared by the levels. In 3D only the levels stop at the first that recognises and
		// skip the hopeless ones; there the loosest tolerance's lists cost more than they save
		// (bench_recog: one model 2.7 against 1.5-2.2 ms, the 10-model database 131-172 against
		// 87-127 ms)
		if (images && (!bounds.members || &bounds.members->table() != &table))
			bounds.members = std::make_shared<MemberCandidates>(table, scene, opts_.levels);
		const auto hyps =
		    hypothesesAt(table, os, opts_, p, focusFilter(scene, os, level, bounds, up_S, images),
		                 images ? bounds.members.get() : nullptr);
		// only the heaviest verify_clusters are verified: the others' means are not wanted
		out.clusters =
		    clusterTransforms(hyps, centroid_O_, p.max_rotation_deg, p.max_translation_mm,
		                      static_cast<size_t>(std::max(0, opts_.verify_clusters)));
	}
	const StageTimer timer(times.verify_3d_ms);
	const auto& clusters = out.clusters;
	for (size_t k = 0; k < clusters.size() && static_cast<int>(k) < opts_.verify_clusters; ++k)
	{
		if (!upright(clusters[k].mean, up_S)) continue;
		auto [T, v] =
		    verifyAndRefine(table_, os.features, clusters[k].mean, p, opts_, occlusionFor(up_S));
		if (!upright(T, up_S) || (images && v.score < minScore(level, up_S, images))) continue;
		out.verified.push_back({T, std::move(v), std::nullopt, k, {}});
	}
	return out;
}

RecognitionResult Recognizer::recognize(const std::vector<Feature>& scene,
                                        const SceneContext& context) const
{
	const auto t0 = std::chrono::steady_clock::now();
	const auto up = context.up();
	const Eigen::Vector3d* up_S = up ? &*up : nullptr;
	const ImageVerifier* images = context.images ? &context.images->get() : nullptr;
	RecognitionResult best;
	best.model = table_.name();
	size_t last = opts_.levels.size();
	int skipped = 0;
	RecognitionTimes times;
	FocusBounds bounds;              // shared by the levels: computed for the coarsest tolerances
	Refinements refined;             // shared by the levels and the plane hypotheses
	std::optional<double> bound_mm;  // computed when a level needs some support
	for (size_t l = 0; l < opts_.levels.size() && l < last; ++l)
	{
		const double need_mm = supportNeeded_mm(l, up_S, images);
		if (opts_.skip_hopeless_levels && need_mm > 0)
		{
			if (!bound_mm) bound_mm = supportBound_mm(scene);
			if (*bound_mm < need_mm)
			{
				++skipped;
				continue;
			}
		}
		RecognitionResult r = atLevel(scene, l, bounds, up_S, images, context.repeat, refined);
		times += r.times;
		if (r.found && !best.found) last = l + 1 + static_cast<size_t>(opts_.confirm_levels);
		if (best.found && !r.found) continue;
		if ((r.found && !best.found) || rankOf(r) > rankOf(best)) best = r;
	}
	if (images && context.plane && opts_.plane.enable &&
	    (!best.found || opts_.plane.run_when == PlaneRunWhen::Always))
	{
		RecognitionResult r = onPlane(scene, *context.plane, *images, refined);
		times += r.times;
		const bool better_candidate =
		    !best.image_score || r.image_score.value_or(0) > *best.image_score;
		if (r.found ? !best.found || rankOf(r) > rankOf(best) : !best.found && better_candidate)
			best = r;
	}
	if (!best.found) best.T_OinS = Eigen::Isometry3d::Identity();
	best.levels_skipped = skipped;
	best.image_refinements = static_cast<int>(refined.made.size());
	best.image_refinements_reused = refined.reused;
	best.image_sweeps_reused = refined.memo.circles_reused;
	best.times = times;
	best.ms =
	    std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
	return best;
}

double Recognizer::supportBound_mm(const std::vector<Feature>& scene) const
{
	double beta = 0, theta = 0;
	for (const auto& p : opts_.levels)
		beta = std::max(beta, verifyBeta_mm(p, opts_)),
		theta = std::max(theta, verifyTheta_rad(p, opts_));
	return SupportBound(table_, beta, theta).supportBound_mm(scene);
}

FocusFilter Recognizer::focusFilter(const std::vector<Feature>& scene, const OrientedScene& os,
                                    size_t level, FocusBounds& bounds, const Eigen::Vector3d* up_S,
                                    const ImageVerifier* images) const
{
	const double need_mm = supportNeeded_mm(level, up_S, images);
	if (!opts_.skip_hopeless_levels || need_mm <= 0) return {};
	if (!bounds.bound)
	{
		double beta = 0, theta = 0;
		for (const auto& p : opts_.levels)
			beta = std::max(beta, verifyBeta_mm(p, opts_)),
			theta = std::max(theta, verifyTheta_rad(p, opts_)),
			bounds.match_beta_mm = std::max(bounds.match_beta_mm, p.position_error_mm);
		bounds.bound = std::make_shared<SupportBound>(table_, beta, theta);
	}
	return [&bounds, &scene, &os, need_mm](size_t f, size_t s)
	{
		const size_t src = os.source[s];
		const auto [it, fresh] = bounds.mm.try_emplace({f, src}, 0.0);
		if (fresh)
			it->second =
			    bounds.bound->focusSupportBound_mm(scene, f, scene[src], bounds.match_beta_mm);
		return it->second >= need_mm;
	};
}

double Recognizer::supportNeeded_mm(size_t level, const Eigen::Vector3d* up_S,
                                    const ImageVerifier* images) const
{
	return minScore(level, up_S, images) * visibleShare(up_S) * modelLength_mm(level);
}

double Recognizer::modelLength_mm(size_t level) const
{
	double len = 0;
	for (const auto& f : table_.features())
		if (f.len_mm >= opts_.levels[level].length_threshold_mm) len += f.len_mm;
	return len;
}

RecognitionResult Recognizer::recognize(const model::WireFrame& scene,
                                        const SceneContext& context) const
{
	return recognize(featuresOf(scene), context);
}

RecognitionResult Recognizer::searchSweep(const std::vector<model::WireFrame>& scenes) const
{
	const auto t0 = std::chrono::steady_clock::now();
	RecognitionResult best;
	best.model = table_.name();
	for (size_t i = 0; i < scenes.size() && !best.found; ++i)
	{
		RecognitionResult r = recognize(scenes[i]);
		if (r.found || r.score > best.score) best = r;
		if (r.found) best.scene_index = static_cast<int>(i);  // r's own is empty
	}
	best.ms =
	    std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
	return best;
}

}  // namespace mrolr::recog
