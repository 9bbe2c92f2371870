// The scores that give up early (ImageVerifier::scoreIfCheaper, scoreIfMore; ScoreCap): each is
// score() itself or, only when the pose cannot beat what it is asked to, nothing.
#include "drawn_box_pair.h"

#include <mrolr/recog/WireFrameBuilder.h>

#include <gtest/gtest.h>

#include <utility>

using namespace mrolr::recog;
using test::boxPose;
using test::Pair;

namespace
{
/** Every figure of the two scores is the same. */
void expectSame(const ImageScore& a, const ImageScore& b)
{
	EXPECT_EQ(a.cost, b.cost);
	EXPECT_EQ(a.score, b.score);
	EXPECT_EQ(a.supported, b.supported);
	EXPECT_EQ(a.considered, b.considered);
	EXPECT_EQ(a.outside, b.outside);
	EXPECT_EQ(a.occluded, b.occluded);
	EXPECT_EQ(a.per_image, b.per_image);
}

/** ScoreCap's rule on a pose's complete counts: it cannot beat @p min_supported and @p max_score
 * when it has fewer supported samples and no higher supported fraction. */
bool cannotBeat(const ImageScore& full, int min_supported, double max_score)
{
	return full.supported < min_supported &&
	       full.supported <= max_score * full.considered * (1 - 1e-12);
}

/** A mug: a body of revolution (its rims, whose limbs the images add) and a handle that hides
 * part of it (SelfOcclusion::hiddenOnBodies, hiddenLimb). */
std::vector<Feature> mug()
{
	WireFrameBuilder b("mug");
	b.circle({0, 0, 0}, 40).circle({0, 0, 55}, 40);
	for (const double y : {-8.0, 8.0})
		b.arc({-40, y, 28}, Eigen::Vector3d::UnitY(), -Eigen::Vector3d::UnitX(), 20, -M_PI / 2,
		      M_PI / 2);
	return featuresOf(b.build());
}
}  // namespace

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
			expectSame(*capped, full);
		}
	}
	EXPECT_GT(below, 100);
	EXPECT_GT(above, 100);
}

// scoreIfMore is empty exactly when the pose's complete counts cannot beat what it is asked to,
// else score() itself, whatever order it tests the samples' sights in: on the box (sights against
// its polytope), on a mug (limbs, sights against its body and handle) and on the box without
// self-occlusion, at poses on and off the drawn box, asked to beat counts below, at and above
// each pose's own.
TEST(ImageVerifier, AScoreAskedToBeatABestIsEmptyExactlyWhenItCannot)
{
	const Pair p;
	const std::vector<Feature> cup = mug();
	const SelfOcclusion cup_occ(cup);
	ASSERT_EQ(cup_occ.revolutionBodies().size(), 1u);
	int empty = 0, asked = 0;
	for (const SightedSamples& samples : {SightedSamples(edgeSamplesOf(p.box, 3), &p.occ),
	                                      SightedSamples(edgeSamplesOf(cup, 3), &cup_occ),
	                                      SightedSamples(edgeSamplesOf(p.box, 3), nullptr)})
	{
		const ImageScore best = p.images.score(samples, boxPose());
		for (int k = 0; k < 60; ++k)
		{
			const Eigen::Isometry3d T = Eigen::Translation3d(0.5 * k - 15, 0.2 * k, 0) * boxPose() *
			                            Eigen::AngleAxisd(0.1 * k, Eigen::Vector3d::UnitZ());
			const ImageScore full = p.images.score(samples, T);
			const double fraction =
			    full.considered ? static_cast<double>(full.supported) / full.considered : 0;
			for (const auto& [min_supported, max_score] :
			     {std::pair{best.supported, best.score}, std::pair{full.supported, fraction},
			      std::pair{full.supported + 1, fraction},
			      std::pair{full.supported + 1, fraction + 1e-9},
			      std::pair{full.supported + 1, fraction - 1e-9}, std::pair{0, 0.0},
			      std::pair{full.supported + 1, 1.0}})
			{
				++asked;
				const auto s = p.images.scoreIfMore(samples, T, min_supported, max_score);
				ASSERT_EQ(!s, cannotBeat(full, min_supported, max_score))
				    << k << ": " << full.supported << " of " << full.considered << " against "
				    << min_supported << ", " << max_score;
				if (!s)
				{
					++empty;
					continue;
				}
				expectSame(*s, full);
			}
		}
	}
	EXPECT_GT(empty, asked / 8);
	EXPECT_GT(asked - empty, asked / 8);
}
