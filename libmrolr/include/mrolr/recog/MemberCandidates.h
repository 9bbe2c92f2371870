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
	/** The same for the loosest tolerance of @p levels (loosestTolerance), remembering the levels'
	 * retests (retest()) when their tolerances form a chain. The loosest of a chain is the
	 * loosest in both terms: then the lists are found under it exactly, and its levels take them
	 * without a retest. */
	MemberCandidates(const ModelTable& model, const std::vector<Feature>& scene,
	                 const std::vector<LevelParams>& levels);

	/** A list of of(): the scene features as codes, and what the levels' retests found of each. */
	struct List
	{
		std::vector<std::uint32_t> codes;
		/** Per code, the rank of the tightest level found consistent and of the loosest found not
		 * (retest()); empty until a level with a rank asks. */
		struct Known
		{
			std::int8_t ok_from = INT8_MAX, fail_to = -1;
		};
		std::vector<Known> known;
	};

	/** The scene features, as 2 × index in the scene + 1 when flipped (increasing), that pass
	 * model feature @p member's unary gate (passesUnaryGate) and are consistent with it, both
	 * under the loosest tolerance, when model feature @p focus is matched to scene feature
	 * @p focus_scene (flipped when @p focus_flipped). Computed on the first call and kept. */
	List& of(size_t focus, size_t member, size_t focus_scene, bool focus_flipped);

	/** The rank of the level of tolerance @p t (levelTolerance) among the levels given, tightest
	 * first, or -1: none given, or their tolerances not a chain. */
	int rankOf(const Tolerance& t) const;

	/** A level's consistent() of the focus match with code @p k of @p list (the level of rank
	 * @p rank): @p test() unless a tighter level found the pair consistent or a looser one found it
	 * not. Consistency is monotone in the tolerance (the premise of these lists), so the answer is
	 * the test's. rank -1: always @p test(). Each answer is remembered. The rank of the lists'
	 * own tolerance: true, untested. */
	template <class Test>
	bool retest(List& list, size_t k, int rank, Test test)
	{
		if (rank < 0) return test();
		if (rank == own_rank_) return true;
		if (list.known.empty()) list.known.resize(list.codes.size());
		List::Known& known = list.known[k];
		if (rank >= known.ok_from) return true;
		if (rank <= known.fail_to) return false;
		const bool ok = test();
		(ok ? known.ok_from : known.fail_to) = static_cast<std::int8_t>(rank);
		return ok;
	}
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
	std::deque<List> lists_;                          ///< a deque: of()'s references stay valid
	/** The levels' distinct tolerances, tightest first, when they form a chain (chainOf); else
	 * empty, and every retest is made. */
	std::vector<Tolerance> chain_;
	int own_rank_ = -1;  ///< the rank in chain_ of the lists' tolerance, or -1
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

/** The tolerance of level @p p: position_error_mm and rotation_deg (in rad). */
Tolerance levelTolerance(const LevelParams& p);

/** The largest position error and rotation of @p levels, widened by 1e-6 mm and 1e-6 rad so that
 * rounding cannot make a level's test accept what this one rejects. */
Tolerance loosestTolerance(const std::vector<LevelParams>& levels);

}  // namespace mrolr::recog
