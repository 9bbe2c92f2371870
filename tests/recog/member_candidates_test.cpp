// MemberCandidates: the clique members' candidates found once under the loosest tolerance give
// every level exactly the matches it finds alone.
#include <mrolr/recog/CliqueMatcher.h>
#include <mrolr/recog/MemberCandidates.h>
#include <mrolr/sim/SyntheticObjects.h>
#include "noisy_table_scenes.h"

#include <gtest/gtest.h>

using namespace mrolr::recog;

namespace
{
bool sameMatches(const std::vector<CliqueMatch>& a, const std::vector<CliqueMatch>& b)
{
	if (a.size() != b.size()) return false;
	for (size_t k = 0; k < a.size(); ++k)
		if (a[k].clique != b[k].clique || a[k].matches != b[k].matches ||
		    a[k].strength_mm != b[k].strength_mm)
			return false;
	return true;
}
}  // namespace

// Noisy, fragmented table scenes of the lab objects, every clique of three models at every level:
// the same matches with and without the shared candidates, and some matches at all. The levels
// run tightest first, then loosest first, so that the remembered retests answer both ways.
TEST(MemberCandidates, EveryLevelFindsTheMatchesItFindsAlone)
{
	const auto opts = RecognitionOptions::defaults();
	std::vector<LevelParams> both_ways = opts.levels;
	both_ways.insert(both_ways.end(), opts.levels.rbegin(), opts.levels.rend());
	size_t matches = 0;
	test::forNoisyTableScenes(
	    {0, 1, 5}, 600,
	    [&](const std::string& name, const ModelTable& table, const std::vector<Feature>& scene)
	    {
		    MemberCandidates members(table, scene, opts.levels);
		    for (const auto& p : both_ways)
		    {
			    ASSERT_GE(members.rankOf(levelTolerance(p)), 0);  // the retests are remembered
			    const OrientedScene os = orientScene(scene, p.length_threshold_mm);
			    for (size_t c = 0; c < table.cliques().size(); ++c)
			    {
				    const auto alone = matchClique(table, c, os, p, opts.max_search_nodes);
				    const auto shared =
				        matchClique(table, c, os, p, opts.max_search_nodes, {}, &members);
				    EXPECT_TRUE(sameMatches(alone, shared))
				        << name << " clique " << c << " beta " << p.position_error_mm;
				    matches += alone.size();
			    }
		    }
	    });
	EXPECT_GT(matches, 100u);
}

// The loosest tolerance is at least every level's, with the margin that keeps rounding out.
TEST(MemberCandidates, LoosestToleranceCoversEveryLevel)
{
	const auto opts = RecognitionOptions::defaults();
	const Tolerance t = loosestTolerance(opts.levels);
	for (const auto& p : opts.levels)
	{
		EXPECT_GT(t.beta_mm, p.position_error_mm);
		EXPECT_GT(t.theta_rad, p.rotation_deg * M_PI / 180);
	}
	EXPECT_NEAR(t.beta_mm, 15, 1e-5);
	EXPECT_NEAR(t.theta_rad, 10 * M_PI / 180, 1e-5);
}

// The retests are remembered only along a chain of tolerances: levels whose position error grows
// while their rotation shrinks are not one, nor are two that differ by less than the 1e-6 that
// keeps rounding out.
TEST(MemberCandidates, RemembersRetestsOnlyAlongAChainOfTolerances)
{
	const auto opts = RecognitionOptions::defaults();
	const ModelTable table(mrolr::sim::makeCup(), 3, 3);
	const std::vector<Feature> scene = featuresOf(mrolr::sim::makeCup());
	const auto levels = [&](std::vector<std::pair<double, double>> mm_deg)
	{
		std::vector<LevelParams> out;
		for (const auto& [mm, deg] : mm_deg)
		{
			LevelParams p = opts.levels.front();
			p.position_error_mm = mm, p.rotation_deg = deg;
			out.push_back(p);
		}
		return out;
	};
	const auto ranks = [&](const std::vector<LevelParams>& ls)
	{
		const MemberCandidates m(table, scene, ls);
		std::vector<int> r;
		for (const auto& p : ls) r.push_back(m.rankOf(levelTolerance(p)));
		return r;
	};
	EXPECT_EQ(ranks(levels({{3, 2}, {2, 1}, {3, 2}, {5, 2}})), (std::vector<int>{1, 0, 1, 2}));
	EXPECT_EQ(ranks(levels({{2, 3}, {3, 2}})), (std::vector<int>{-1, -1}));
	EXPECT_EQ(ranks(levels({{2, 1}, {2 + 1e-9, 1}})), (std::vector<int>{-1, -1}));
	const MemberCandidates alone(table, scene, loosestTolerance(opts.levels));
	EXPECT_EQ(alone.rankOf(levelTolerance(opts.levels.front())), -1);
}

// Along a chain the lists are found under its loosest tolerance itself: each of their pairs is
// consistent under it, so its level takes them without a test, while a tighter level tests them.
// A cup seen as its model (every pair of its features), the default levels.
TEST(MemberCandidates, TheLoosestLevelOfAChainTakesItsListsUntested)
{
	const auto levels = RecognitionOptions::defaults().levels;
	const ModelTable table(mrolr::sim::makeCup(), 3, 3);
	const std::vector<Feature> scene = featuresOf(mrolr::sim::makeCup());
	MemberCandidates m(table, scene, levels);
	const Tolerance top = loosestTolerance(levels);  // the chain's last, widened by 1e-6
	const Tolerance own(top.beta_mm - 1e-6, top.theta_rad - 1e-6);
	const int top_rank = m.rankOf(own), tighter = m.rankOf(levelTolerance(levels.front()));
	ASSERT_GT(top_rank, 0);
	ASSERT_EQ(tighter, 0);
	const auto& mf = table.features();
	size_t pairs = 0, tested = 0;
	for (size_t f = 0; f < mf.size(); ++f)
		for (size_t j = 0; j < mf.size(); ++j)
		{
			if (j == f) continue;
			auto& list = m.of(f, j, f, false);
			for (size_t e = 0; e < list.codes.size(); ++e, ++pairs)
			{
				const Feature& sb = list.codes[e] % 2 ? scene[list.codes[e] / 2].flipped()
				                                      : scene[list.codes[e] / 2];
				EXPECT_TRUE(consistent(table.relation(f, j), mf[f], mf[j], scene[f], sb, own))
				    << f << " " << j;
				EXPECT_TRUE(m.retest(list, e, top_rank, [&] { return ++tested, false; }));
				m.retest(list, e, tighter, [&] { return ++tested, true; });
			}
		}
	EXPECT_GT(pairs, 20u);
	EXPECT_EQ(tested, pairs);  // the tighter level's tests alone
}
