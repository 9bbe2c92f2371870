// mayBeConsistent, the packed quick form of consistent() that MemberCandidates runs first: it
// keeps every pair consistent() accepts, and it sets most of the others aside.
#include <mrolr/recog/PairPrefilter.h>
#include <mrolr/sim/SyntheticObjects.h>

#include "recog_test_util.h"

#include <gtest/gtest.h>

#include <random>

using namespace mrolr::recog;
using test::randomPose;

namespace
{
/** @p f moved by a small random motion (up to @p mm and @p rad), as a noisy scene sees it. */
Feature jittered(const Feature& f, std::mt19937& rng, double mm, double rad)
{
	std::uniform_real_distribution<> u(-1, 1);
	const Eigen::Vector3d axis = Eigen::Vector3d(u(rng), u(rng), u(rng)).normalized();
	const Eigen::Isometry3d dT =
	    Eigen::Translation3d(Eigen::Vector3d(u(rng), u(rng), u(rng)) * mm) *
	    Eigen::Translation3d(f.m) * Eigen::AngleAxisd(rad * u(rng), axis) *
	    Eigen::Translation3d(-f.m);
	return f.transformed(dT);
}
}  // namespace

// Every pair of each lab object's features, seen at a random pose with the second feature moved
// by up to 3 times the tolerance (many pairs sit near its bounds), both orientations, and the
// other objects' features as distractors.
TEST(PairPrefilter, KeepsEveryPairConsistentAcceptsAndSetsMostOthersAside)
{
	std::mt19937 rng(11);
	const Tolerance tol(6, 4 * M_PI / 180);
	const auto objects = mrolr::sim::makeLabObjects();
	int accepted = 0, rejected = 0, set_aside = 0;
	for (const auto& wf : objects)
	{
		const auto fs = featuresOf(wf);
		const Eigen::Isometry3d T = randomPose(rng);
		std::vector<Feature> scene;
		for (const auto& f : fs)
			for (int k = 0; k < 3; ++k)
			{
				const Feature g =
				    jittered(f.transformed(T), rng, 3 * tol.beta_mm, 3 * tol.theta_rad);
				scene.push_back(g), scene.push_back(g.flipped());
			}
		for (const auto& other : objects)
			for (const auto& f : featuresOf(other)) scene.push_back(f.transformed(randomPose(rng)));
		PackedFeatures packed;
		for (const auto& s : scene) packed.push_back(s);
		std::vector<std::int64_t> keep;
		for (size_t i = 0; i < fs.size(); ++i)
			for (size_t j = 0; j < fs.size(); ++j)
			{
				if (i == j) continue;
				const PairRelation m = relateModel(fs[i], fs[j]);
				const Feature a = fs[i].transformed(T);
				mayBeConsistent(m, fs[i], fs[j], a, packed, tol, keep);
				ASSERT_EQ(keep.size(), scene.size());
				for (size_t k = 0; k < scene.size(); ++k)
				{
					const bool c = consistent(m, fs[i], fs[j], a, scene[k], tol);
					if (c)
					{
						EXPECT_NE(keep[k], 0) << wf.name << " " << i << " " << j << " " << k;
					}
					(c ? accepted : rejected) += 1;
					set_aside += !c && !keep[k] ? 1 : 0;
				}
			}
	}
	EXPECT_GT(accepted, 1000);
	// the angle and h alone set aside 93 % of them; with the intervals too, more than 95 %
	EXPECT_GT(set_aside, rejected * 0.95);
}
