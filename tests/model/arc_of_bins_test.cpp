// arcOfBins (ArcOfBins.h): the circle minus its longest run of uncovered bins.
#include <mrolr/model/ArcOfBins.h>

#include <gtest/gtest.h>

using mrolr::model::arcOfBins;

TEST(ArcOfBins, EveryBinCoveredIsTheWholeCircle)
{
	std::array<bool, 4> all{true, true, true, true};
	const auto [t1, t2] = arcOfBins(all, -M_PI);
	EXPECT_DOUBLE_EQ(t1, 0);
	EXPECT_DOUBLE_EQ(t2, 2 * M_PI);
}

TEST(ArcOfBins, TheLongestGapIsCutOutWrappingRound)
{
	// bins of 90°: covered 0 and 1, gap 2-3; the arc starts after the gap (bin 0) and spans 180°
	const auto [t1, t2] = arcOfBins(std::array<bool, 4>{true, true, false, false}, 0.0);
	EXPECT_NEAR(std::remainder(t1, 2 * M_PI), 0, 1e-12);
	EXPECT_NEAR(t2 - t1, M_PI, 1e-12);
	// a gap that wraps past the last bin: covered 1 and 2, gap 3-0; start offset −π
	const auto [u1, u2] = arcOfBins(std::array<bool, 4>{false, true, true, false}, -M_PI);
	EXPECT_NEAR(std::remainder(u1 - (-M_PI + M_PI / 2), 2 * M_PI), 0, 1e-12);  // angles mod 2π
	EXPECT_NEAR(u2 - u1, M_PI, 1e-12);
	// of two gaps the longer one goes: covered 0 and 3 of 6, gaps 1-2 and 4-5 tie, the first wins
	const auto [v1, v2] =
	    arcOfBins(std::array<bool, 6>{true, false, false, true, false, false}, 0.0);
	EXPECT_NEAR(v2 - v1, 4 * M_PI / 3, 1e-12);
}

TEST(ArcOfBins, NoBinCoveredIsAnEmptyArc)
{
	const auto [t1, t2] = arcOfBins(std::array<bool, 3>{}, 0.0);
	EXPECT_DOUBLE_EQ(t2 - t1, 0);
}
