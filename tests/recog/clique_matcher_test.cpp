// matchClique: the clique size a level asks for only filters the sets it finds (thesis 6.3.2,
// parameter (a)); a focus match that cannot reach it is given up before its search, which must not
// lose a set that reaches it.
#include <mrolr/recog/CliqueMatcher.h>
#include <mrolr/recog/MemberCandidates.h>
#include <mrolr/sim/SyntheticObjects.h>
#include <mrolr/sim/SyntheticScene.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <tuple>

using namespace mrolr::recog;
using namespace mrolr::sim;

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
	const auto objects = makeLabObjects();
	const auto opts = RecognitionOptions::defaults();
	SceneNoise noise;
	noise.endpoint_sigma_mm = 0.7, noise.fragment_probability = 0.4, noise.missing_fraction = 0.1;
	size_t kept = 0, dropped = 0;
	for (const size_t k : {0u, 2u, 5u})
	{
		const ModelTable table(objects[k], opts.auto_clique_count, opts.auto_clique_size,
		                       opts.auto_cliques, opts.file_cliques);
		const auto scene =
		    featuresOf(makeTableScene(objects, static_cast<int>(k), 3, noise, 700 + k).scene);
		MemberCandidates members(table, scene, loosestTolerance(opts.levels));
		for (const auto& p : opts.levels)
		{
			const OrientedScene os = orientScene(scene, p.length_threshold_mm);
			LevelParams any = p;
			any.clique_size = 1;
			for (size_t c = 0; c < table.cliques().size(); ++c)
				for (MemberCandidates* m : {static_cast<MemberCandidates*>(nullptr), &members})
				{
					const auto all = matchClique(table, c, os, any, opts.max_search_nodes, {}, m);
					const auto sized = matchClique(table, c, os, p, opts.max_search_nodes, {}, m);
					const size_t size = static_cast<size_t>(p.clique_size);
					EXPECT_EQ(setsOf(sized, 0), setsOf(all, size))
					    << objects[k].name << " clique " << c << " size " << p.clique_size;
					kept += sized.size();
					dropped += all.size() - setsOf(all, size).size();
				}
		}
	}
	// both kinds occur: sets that reach the size and sets that do not
	EXPECT_GT(kept, 100u);
	EXPECT_GT(dropped, 100u);
}
