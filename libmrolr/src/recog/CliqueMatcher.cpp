#include <mrolr/recog/CliqueMatcher.h>

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace mrolr::recog
{
namespace
{
constexpr size_t kAlternatives = 3;  // equally large consistent sets kept per focus match

/** Depth-first search for the largest pairwise-consistent choice of one candidate (or none) per
 * clique member, with a node budget. */
class ConsistentSetSearch
{
 public:
	ConsistentSetSearch(const ModelTable& m, const IndexClique& clique, const OrientedScene& s,
	                    const Tolerance& t, int max_nodes)
	    : model_(m), scene_(s), tol_(t), max_nodes_(max_nodes), slots_(clique.members.size() + 1)
	{
		// the angle test's range of each pair of the clique's features (focus, then members)
		const auto feature = [&](size_t slot)
		{ return slot == 0 ? clique.focus : clique.members[slot - 1]; };
		for (size_t a = 0; a < slots_; ++a)
			for (size_t b = 0; b < slots_; ++b)
				angles_.push_back(cosineRange(m.relation(feature(a), feature(b)), t));
	}

	/** Starts the candidates of a new focus match: members are then added in clique order. */
	void clearMembers() { members_.clear(), by_member_.clear(); }
	/** Appends the next member's candidates to this (they stay in the order appended). */
	std::vector<FeatureMatch>& candidates() { return by_member_; }
	/** Closes the member whose candidates were appended since the last call; true when it has
	 * none. */
	bool closeMember()
	{
		const size_t begin = members_.empty() ? 0 : members_.back().end;
		members_.push_back({begin, by_member_.size()});
		return begin == by_member_.size();
	}

	/** The largest sets for @p focus among the members' candidates, each search with its own node
	 * budget; the search's buffers are kept from one focus match to the next. */
	const std::vector<std::vector<FeatureMatch>>& run(const FeatureMatch& focus)
	{
		budget_ = max_nodes_;
		// the members by their number of candidates (std::sort, as on the lists themselves: the
		// same order)
		order_.resize(members_.size());
		for (size_t k = 0; k < order_.size(); ++k) order_[k] = k;
		std::sort(order_.begin(), order_.end(),
		          [&](size_t a, size_t b) { return members_[a].size() < members_[b].size(); });
		cands_.clear(), first_.clear(), slot_.clear();
		for (const size_t k : order_)
		{
			first_.push_back(cands_.size());
			slot_.insert(slot_.end(), members_[k].size(), k + 1);
			cands_.insert(cands_.end(), by_member_.begin() + static_cast<long>(members_[k].begin),
			              by_member_.begin() + static_cast<long>(members_[k].end));
		}
		first_.push_back(cands_.size());
		const size_t n = cands_.size();
		pairs_ = n;
		// a table of n² answers; beyond kMaxKnown (a scene of thousands of candidates) every pair
		// is asked afresh instead
		known_.assign(n * n <= kMaxKnown ? n * n : 0, kUnknown);
		chosen_.assign(1, focus), chosen_index_.assign(1, 0);
		best_.resize(1), best_.front() = chosen_;  // the buffers kept from the last focus match
		dfs(0);
		return best_;
	}

 private:
	static constexpr std::int8_t kUnknown = -1;
	static constexpr size_t kMaxKnown = size_t{1} << 22;  // 4 MiB

	/** Whether candidates @p a and @p b (indices over all members' lists) are consistent: asked
	 * once per pair, however many branches of the search meet it. */
	bool pairConsistent(size_t a, const FeatureMatch& x, size_t b, const FeatureMatch& c)
	{
		const auto ask = [&]
		{
			const auto& mf = model_.features();
			return consistent(model_.relation(x.model, c.model),
			                  angles_[slot_[a] * slots_ + slot_[b]], mf[x.model], mf[c.model],
			                  scene_.oriented[x.oriented], scene_.oriented[c.oriented], tol_);
		};
		if (known_.empty()) return ask();
		std::int8_t& k = known_[a * pairs_ + b];
		if (k == kUnknown) k = ask() ? 1 : 0;
		return k == 1;
	}

	/** Whether @p c (index @p ci), a candidate of the focus match (memberCandidates: consistent
	 * with it), is consistent with the other chosen matches too. */
	bool fits(const FeatureMatch& c, size_t ci)
	{
		for (size_t k = 1; k < chosen_.size(); ++k)
		{
			const FeatureMatch& x = chosen_[k];
			if (x.scene() == c.scene()) return false;
			if (!pairConsistent(chosen_index_[k], x, ci, c)) return false;
		}
		return true;
	}

	/** Keeps the largest sets found (up to kAlternatives of equal size): a nearly symmetric object
	 * can give the true and a mirrored assignment of the same size. */
	void record()
	{
		if (chosen_.size() > best_.front().size())
			best_.resize(1), best_.front() = chosen_;
		else if (chosen_.size() == best_.front().size() && chosen_.size() > 1 &&
		         best_.size() < kAlternatives && chosen_ != best_.back())
			best_.push_back(chosen_);
	}

	void dfs(size_t k)
	{
		record();
		const size_t members = first_.size() - 1;
		if (k == members || --budget_ <= 0) return;
		// below here no set is larger than the largest found so far, and one as large is kept
		// only while the alternatives are not full: past that nothing found here is kept
		const size_t reach = chosen_.size() + (members - k), best = best_.front().size();
		if (reach < best || (reach == best && best_.size() == kAlternatives)) return;
		for (size_t i = first_[k]; i < first_[k + 1]; ++i)
		{
			const FeatureMatch& c = cands_[i];
			if (!fits(c, i)) continue;
			chosen_.push_back(c), chosen_index_.push_back(i);
			dfs(k + 1);
			chosen_.pop_back(), chosen_index_.pop_back();
			if (budget_ <= 0) return;
		}
		dfs(k + 1);
	}

	const ModelTable& model_;
	const OrientedScene& scene_;
	Tolerance tol_;
	int max_nodes_;
	int budget_ = 0;
	/** A member's candidates in by_member_: [begin, end). */
	struct Range
	{
		size_t begin, end;
		size_t size() const { return end - begin; }
	};
	std::vector<FeatureMatch> by_member_;  ///< the members' candidates, in clique order
	std::vector<Range> members_;
	std::vector<size_t> order_;        ///< the members by their number of candidates
	std::vector<FeatureMatch> cands_;  ///< the candidates in that order
	size_t slots_;                     ///< the clique's features: focus, then members
	std::vector<CosineRange> angles_;  ///< cosineRange of each pair of slots, slots_ × slots_
	std::vector<size_t> slot_;         ///< each candidate's slot
	std::vector<size_t> first_;        ///< index of each member's first candidate; then the end
	size_t pairs_ = 0;                 ///< candidates of all members
	std::vector<std::int8_t> known_;   ///< pairConsistent's answers (kUnknown: not asked yet)
	std::vector<FeatureMatch> chosen_;
	std::vector<size_t> chosen_index_;  ///< chosen_'s candidate indices (the focus's unused)
	std::vector<std::vector<FeatureMatch>> best_;
};

/** Appends to @p out the scene matches of member j (among its gated features) consistent with
 * the focus match. */
void memberCandidates(const ModelTable& model, size_t j, const std::vector<size_t>& gated,
                      const FeatureMatch& focus, const OrientedScene& scene, const Tolerance& tol,
                      std::vector<FeatureMatch>& out)
{
	const auto& mf = model.features();
	const auto& rel = model.relation(focus.model, j);
	const CosineRange angle = cosineRange(rel, tol);
	for (size_t o : gated)
		if (o / 2 != focus.scene() &&
		    consistent(rel, angle, mf[focus.model], mf[j], scene.oriented[focus.oriented],
		               scene.oriented[o], tol))
			out.push_back({j, o});
}

/** The same, seeking them among the scene features @p members lists for the focus match
 * (@p kept_index: each scene feature's index among the level's kept ones, -1 if not kept; @p rank:
 * the level's in @p members, for its remembered retests). */
void memberCandidates(const ModelTable& model, size_t j, const FeatureMatch& focus,
                      const OrientedScene& scene, const LevelParams& p, const Tolerance& tol,
                      MemberCandidates& members, int rank, const std::vector<int>& kept_index,
                      std::vector<FeatureMatch>& out)
{
	const auto& mf = model.features();
	const auto& rel = model.relation(focus.model, j);
	const CosineRange angle = cosineRange(rel, tol);
	const size_t src = scene.source[focus.scene()];
	MemberCandidates::List& list = members.of(focus.model, j, src, focus.oriented % 2 == 1);
	for (size_t e = 0; e < list.codes.size(); ++e)
	{
		const std::uint32_t code = list.codes[e];
		const int k = kept_index[code / 2];
		if (k < 0) continue;
		const size_t o = 2 * static_cast<size_t>(k) + code % 2;
		if (o / 2 == focus.scene() || !passesUnaryGate(mf[j], scene.oriented[o], p, false))
			continue;
		const auto test = [&]
		{
			return consistent(rel, angle, mf[focus.model], mf[j], scene.oriented[focus.oriented],
			                  scene.oriented[o], tol);
		};
		if (members.retest(list, e, rank, test)) out.push_back({j, o});
	}
}

/** Each of the @p n scene features' index among @p scene's kept ones (-1 when not kept). */
std::vector<int> keptIndex(const OrientedScene& scene, size_t n)
{
	std::vector<int> out(n, -1);
	for (size_t k = 0; k < scene.source.size(); ++k) out[scene.source[k]] = static_cast<int>(k);
	return out;
}

double strengthOf(const ModelTable& model, const std::vector<FeatureMatch>& ms)
{
	double s = 0;
	for (const auto& m : ms) s += model.features()[m.model].len_mm;
	return s;
}
}  // namespace

OrientedScene orientScene(const std::vector<Feature>& scene, double min_len_mm)
{
	OrientedScene s;
	for (size_t i = 0; i < scene.size(); ++i)
	{
		const Feature& f = scene[i];
		if (f.len_mm < min_len_mm) continue;
		s.source.push_back(i);
		s.features.push_back(f);
		s.oriented.push_back(f);
		s.oriented.push_back(f.flipped());
	}
	return s;
}

std::vector<size_t> passingUnaryGate(const Feature& m, const std::vector<Feature>& oriented,
                                     const LevelParams& p, bool focus)
{
	std::vector<size_t> out;
	for (size_t o = 0; o < oriented.size(); ++o)
		if (passesUnaryGate(m, oriented[o], p, focus)) out.push_back(o);
	return out;
}

std::vector<CliqueMatch> matchClique(const ModelTable& model, size_t clique_index,
                                     const OrientedScene& scene, const LevelParams& p,
                                     int max_nodes, const FocusFilter& focus_ok,
                                     MemberCandidates* members)
{
	const auto& clique = model.cliques().at(clique_index);
	const Tolerance tol = levelTolerance(p);
	const Feature& mfocus = model.features()[clique.focus];
	std::vector<std::vector<size_t>> gated;
	std::vector<int> kept_index;
	const int rank = members ? members->rankOf(tol) : -1;  // the level's, for retest()
	if (members)
		kept_index = keptIndex(scene, members->sceneSize());
	else
		for (size_t j : clique.members)
			gated.push_back(passingUnaryGate(model.features()[j], scene.oriented, p, false));
	std::vector<CliqueMatch> out;
	// a set has the focus and at most one match per member with candidates: once more members
	// than this have none, no set of the focus reaches clique_size
	const int spare = static_cast<int>(clique.members.size()) + 1 - p.clique_size;
	if (spare < 0) return out;
	ConsistentSetSearch search(model, clique, scene, tol, max_nodes);
	for (size_t o : passingUnaryGate(mfocus, scene.oriented, p, true))
	{
		if (focus_ok && !focus_ok(clique.focus, o / 2)) continue;
		const FeatureMatch focus{clique.focus, o};
		search.clearMembers();
		int without = 0;
		for (size_t k = 0; k < clique.members.size() && without <= spare; ++k)
		{
			if (members)
				memberCandidates(model, clique.members[k], focus, scene, p, tol, *members, rank,
				                 kept_index, search.candidates());
			else
				memberCandidates(model, clique.members[k], gated[k], focus, scene, tol,
				                 search.candidates());
			without += search.closeMember() ? 1 : 0;
		}
		if (without > spare) continue;
		for (const auto& ms : search.run(focus))
			if (static_cast<int>(ms.size()) >= p.clique_size)
				out.push_back({clique_index, ms, strengthOf(model, ms)});
	}
	std::sort(out.begin(), out.end(),
	          [](const CliqueMatch& a, const CliqueMatch& b)
	          {
		          if (a.matches.size() != b.matches.size())
			          return a.matches.size() > b.matches.size();
		          return a.strength_mm > b.strength_mm;
	          });
	return out;
}

}  // namespace mrolr::recog
