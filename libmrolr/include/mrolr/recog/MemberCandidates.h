#pragma once
/** The scene features that can join a focus match in a clique, for one scene and every level at
 * once (thesis 6.3.2's pairwise test, paper 3.2). Every level tests each clique member's scene
 * candidates against the focus match; a pair consistent under a level's tolerance is consistent
 * under any looser one, so the pairs consistent under the loosest tolerance of all levels are
 * found once per scene and each level tests only those. The answers are the levels' own. */

#include <mrolr/recog/ModelTable.h>
#include <mrolr/recog/PairPrefilter.h>
#include <mrolr/recog/PairRelation.h>
#include <mrolr/recog/RecognitionOptions.h>

#include <cstdint>
#include <deque>
#include <unordered_map>
#include <vector>

namespace mrolr::recog
{
class MemberCandidates
{
 public:
	/** @p scene all features of the scene (not only a level's); @p loosest a tolerance at least
	 * as loose as every level's (loosestTolerance). */
	MemberCandidates(const ModelTable& model, const std::vector<Feature>& scene,
	                 const Tolerance& loosest);

	/** The scene features, as 2 × index in the scene + 1 when flipped (increasing), that pass
	 * model feature @p member's unary gate (passesUnaryGate) and are consistent with it, both
	 * under the loosest tolerance, when model feature @p focus is matched to scene feature
	 * @p focus_scene (flipped when @p focus_flipped). Computed on the first call and kept. */
	const std::vector<std::uint32_t>& of(size_t focus, size_t member, size_t focus_scene,
	                                     bool focus_flipped);
	const ModelTable& table() const { return model_; }
	size_t sceneSize() const { return oriented_.size() / 2; }

 private:
	const ModelTable& model_;
	std::vector<Feature> oriented_;  ///< 2k: scene feature k, 2k + 1: flipped
	Tolerance loosest_;
	/** The lists computed: per (focus, member) pair asked, an index into lists_ per oriented focus
	 * scene feature (-1: not yet); a direct look-up (a hash map's cost more than the lists). */
	std::vector<std::int32_t> pair_slot_;             ///< per focus × member: into by_pair_, or -1
	std::vector<std::vector<std::int32_t>> by_pair_;  ///< per oriented scene feature: into lists_
	std::deque<std::vector<std::uint32_t>> lists_;    ///< a deque: of()'s references stay valid
	/** The oriented scene features passing a model feature's gate, also packed for
	 * mayBeConsistent (PairPrefilter.h). */
	struct Gated
	{
		std::vector<size_t> index;
		PackedFeatures packed;
	};
	std::unordered_map<size_t, Gated> gated_;  ///< per model feature, on first use
	std::vector<std::int64_t> keep_;           ///< of()'s prefilter answers
	const Gated& gatedFor(size_t member);
};

/** The largest position error and rotation of @p levels, widened by 1e-6 mm and 1e-6 rad so that
 * rounding cannot make a level's test accept what this one rejects. */
Tolerance loosestTolerance(const std::vector<LevelParams>& levels);

}  // namespace mrolr::recog
