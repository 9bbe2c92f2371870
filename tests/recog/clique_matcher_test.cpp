// matchClique: the clique size a level asks for only filters the sets it finds (thesis 6.3,
// parameter (a)); a focus match that cannot reach it is given up before its search, which must not
// lose a set that reaches it.
#include <mrolr/recog/CliqueMatcher.h>
#include <mrolr/recog/MemberCandidates.h>
#include "noisy_table_scenes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <tuple>

using namespace mrolr::recog;

namespace
{
using SetKey = std::vector<std::tuple<size_t, size_t>>;

/** The sets of @p ms with at least @p size matches, in one order (matchClique's ties are not). */
std::vector<std::tuple<size_t, SetKey, double>> setsOf(const std::vector<CliqueMatch>& ms,
                                                       size_t size)
{
	std::vector<std::tuple<size_t, SetKey, double>> out;
	for (const auto& m : ms)
	{
		if (m.matches.size() < size) continue;
		SetKey key;
		for (const auto& f : m.matches) key.emplace_back(f.model, f.oriented);
		out.emplace_back(m.clique, key, m.strength_mm);
	}
	std::sort(out.begin(), out.end());
	return out;
}
}  // namespace

// Noisy, fragmented table scenes of three lab objects, every clique at every level's tolerances,
// with and without the shared member candidates: the sets found for the level's clique size are
// those found for a clique size of 1 that have that many matches.
TEST(CliqueMatcher, TheCliqueSizeOnlyFiltersTheSets)
{
	const auto opts = RecognitionOptions::defaults();
	size_t kept = 0, dropped = 0;
	const auto check = [&](const std::string& name, const ModelTable& table,
	                       const std::vector<Feature>& scene)
	{
		MemberCandidates members(table, scene, loosestTolerance(opts.levels));
		for (const auto& p : opts.levels)
		{
			const OrientedScene os = orientScene(scene, p.length_threshold_mm);
			LevelParams any = p;
			any.clique_size = 1;
			const size_t size = static_cast<size_t>(p.clique_size);
			for (size_t c = 0; c < table.cliques().size(); ++c)
				for (MemberCandidates* m : {static_cast<MemberCandidates*>(nullptr), &members})
				{
					const auto all = matchClique(table, c, os, any, opts.max_search_nodes, {}, m);
					const auto sized = matchClique(table, c, os, p, opts.max_search_nodes, {}, m);
					EXPECT_EQ(setsOf(sized, 0), setsOf(all, size))
					    << name << " clique " << c << " size " << p.clique_size;
					kept += sized.size();
					dropped += all.size() - setsOf(all, size).size();
				}
		}
	};
	test::forNoisyTableScenes({0, 2, 5}, 700, check);
	// both kinds occur: sets that reach the size and sets that do not
	EXPECT_GT(kept, 100u);
	EXPECT_GT(dropped, 100u);
}
