#pragma once
/** Clique matching (thesis 6.3.2, paper 3.2): for a model clique, every scene feature that passes
 * the unary gates of the focus feature is a candidate; each candidate is grown to a maximal set of
 * scene matches for the other clique members that are pairwise consistent with each other and
 * with the focus match, no model or scene feature used twice. */

#include <mrolr/recog/MemberCandidates.h>
#include <mrolr/recog/ModelTable.h>
#include <mrolr/recog/RecognitionOptions.h>

#include <cmath>
#include <functional>
#include <vector>

namespace mrolr::recog
{
/** A scene prepared for matching: every feature at least the level's length threshold long, in both
 * orientations (oriented index 2k is feature k as given, 2k+1 flipped). */
struct OrientedScene
{
	std::vector<Feature> features;  ///< the kept scene features
	std::vector<Feature> oriented;  ///< 2 × features.size()
	std::vector<size_t> source;     ///< index in the given scene of each kept feature
};

/** Keeps the features of @p scene at least @p min_len_mm long and adds their flipped copies. */
OrientedScene orientScene(const std::vector<Feature>& scene, double min_len_mm);

/** One model feature matched to one oriented scene feature. */
struct FeatureMatch
{
	size_t model = 0;     ///< index into ModelTable::features()
	size_t oriented = 0;  ///< index into OrientedScene::oriented
	size_t scene() const { return oriented / 2; }
	bool operator==(const FeatureMatch& o) const
	{
		return model == o.model && oriented == o.oriented;
	}
	bool operator!=(const FeatureMatch& o) const { return !(*this == o); }
};

/** A matched clique: the focus match first, then the members found. */
struct CliqueMatch
{
	size_t clique = 0;
	std::vector<FeatureMatch> matches;
	double strength_mm = 0;  ///< summed lengths of the matched model features
};

/** Unary gate: same kind; a scene line no longer than the model line plus 2 beta and, for a focus,
 * at least length_ratio times it; conic radii within 2 beta + 5 %. Inline: every level asks it of
 * each member candidate. */
inline bool passesUnaryGate(const Feature& m, const Feature& s, const LevelParams& p, bool focus)
{
	if (m.kind != s.kind) return false;
	const double b2 = 2 * p.position_error_mm;
	if (s.len_mm > m.len_mm + b2 + (m.isLine() ? 0.0 : 0.05 * m.len_mm)) return false;
	if (focus && s.len_mm < p.length_ratio * m.len_mm) return false;
	if (m.isLine()) return true;
	const double rtol = b2 + 0.05 * m.a_mm;
	return std::abs(s.a_mm - m.a_mm) <= rtol && std::abs(s.b_mm - m.b_mm) <= rtol;
}

/** The indices of the features of @p oriented that pass model feature @p m's unary gate at @p p
 * (passesUnaryGate), increasing. */
std::vector<size_t> passingUnaryGate(const Feature& m, const std::vector<Feature>& oriented,
                                     const LevelParams& p, bool focus);

/** Says whether a focus match (model feature index, index into OrientedScene::features) is worth
 * searching; empty = every one. */
using FocusFilter = std::function<bool(size_t model_focus, size_t scene_feature)>;

/** All matches of clique @p clique_index with at least p.clique_size features, largest and
 * strongest first. @p max_nodes bounds the search per focus candidate; focus candidates that
 * @p focus_ok rejects are not searched. With @p members (built on @p model and the scene
 * @p scene was oriented from, for tolerances at least as loose as @p p's) each member's
 * candidates are sought among those it lists instead of the whole scene: the same matches. */
std::vector<CliqueMatch> matchClique(const ModelTable& model, size_t clique_index,
                                     const OrientedScene& scene, const LevelParams& p,
                                     int max_nodes, const FocusFilter& focus_ok = {},
                                     MemberCandidates* members = nullptr);

}  // namespace mrolr::recog
