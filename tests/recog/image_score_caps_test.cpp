// The scores that give up early (ImageVerifier::scoreIfCheaper, scoreIfMore; ScoreCap): each is
// score() itself or, only when the pose cannot beat what it is asked to, nothing.
#include "drawn_box_pair.h"

#include <gtest/gtest.h>

#include <utility>

using namespace mrolr::recog;
using test::boxPose;
using test::Pair;

// scoreIfCheaper is score() when the cost is below the cap and empty when it is not, whatever the
// pose (on the box, moved off it, mostly out of view) and the cap (between the costs seen).
TEST(ImageVerifier, AScoreAskedBelowACostIsTheScoreOrNothing)
{
	const Pair p;
	const SightedSamples samples(edgeSamplesOf(p.box, 3), &p.occ);
	std::vector<Eigen::Isometry3d> poses;
	for (int k = 0; k < 40; ++k)
		poses.push_back(Eigen::Translation3d(0.7 * k - 8, 0.3 * k, 0) * boxPose() *
		                Eigen::AngleAxisd(0.02 * k, Eigen::Vector3d::UnitZ()));
	poses.push_back(Eigen::Translation3d(400, 0, 0) * boxPose());  // out of view: cost 1e300
	std::vector<double> caps = {0.0, 0.5, 1e300};
	for (const auto& T : poses) caps.push_back(p.images.score(samples, T).cost);
	int below = 0, above = 0;
	for (const auto& T : poses)
	{
		const ImageScore full = p.images.score(samples, T);
		for (const double cap : caps)
		{
			const auto capped = p.images.scoreIfCheaper(samples, T, cap);
			ASSERT_EQ(capped.has_value(), full.cost < cap)
			    << "cap " << cap << " cost " << full.cost;
			if (!capped) ++above;
			if (!capped) continue;
			++below;
			EXPECT_EQ(capped->cost, full.cost);
			EXPECT_EQ(capped->score, full.score);
			EXPECT_EQ(capped->supported, full.supported);
			EXPECT_EQ(capped->considered, full.considered);
			EXPECT_EQ(capped->outside, full.outside);
			EXPECT_EQ(capped->per_image, full.per_image);
		}
	}
	EXPECT_GT(below, 100);
	EXPECT_GT(above, 100);
}

// scoreIfMore is score() or, only when the pose has neither more supported samples nor a higher
// score than asked, nothing; on poses moved off the box it gives up on most.
TEST(ImageVerifier, AScoreAskedToBeatABestIsTheScoreOrNothing)
{
	const Pair p;
	const SightedSamples samples(edgeSamplesOf(p.box, 3), &p.occ);
	const ImageScore best = p.images.score(samples, boxPose());
	int empty = 0, asked = 0;
	for (int k = 0; k < 60; ++k)
	{
		const Eigen::Isometry3d T = Eigen::Translation3d(0.5 * k - 15, 0.2 * k, 0) * boxPose() *
		                            Eigen::AngleAxisd(0.1 * k, Eigen::Vector3d::UnitZ());
		const ImageScore full = p.images.score(samples, T);
		for (const auto& [min_supported, max_score] :
		     {std::pair{best.supported, best.score}, std::pair{full.supported, full.score},
		      std::pair{full.supported + 1, full.score}, std::pair{0, 0.0}})
		{
			++asked;
			const auto s = p.images.scoreIfMore(samples, T, min_supported, max_score);
			if (!s)
			{
				++empty;
				EXPECT_LT(full.supported, min_supported) << k;
				EXPECT_LE(full.score, max_score) << k;
				continue;
			}
			EXPECT_EQ(s->cost, full.cost);
			EXPECT_EQ(s->score, full.score);
			EXPECT_EQ(s->supported, full.supported);
			EXPECT_EQ(s->considered, full.considered);
		}
	}
	EXPECT_GT(empty, asked / 8);
}
