// The refinement's local search (ImageVerifier::edgeLines, edgeLineSearch through refine): the
// edge-line residuals' derivatives predict what a step does, the refined pose fits the drawn edges
// and lands on the drawn pose across the view, and the search's reach is bounded.
#include "drawn_box_pair.h"
#include "recog_test_util.h"

#include <gtest/gtest.h>

#include <Eigen/Cholesky>

#include <cmath>

using namespace mrolr::recog;
using test::boxPose;
using test::Pair;

namespace
{
Eigen::Isometry3d stepped(const Eigen::Isometry3d& T, const Eigen::Vector3d& c_L,
                          const Eigen::Matrix<double, 6, 1>& d)
{
	const Eigen::Vector3d w = d.tail<3>();
	return Eigen::Translation3d(d.head<3>()) * Eigen::Translation3d(c_L) *
	       Eigen::AngleAxisd(w.norm(), w.normalized()) * Eigen::Translation3d(-c_L) * T;
}
}  // namespace

// The derivatives are right: from a pose shifted by (1.2, -0.9, 0.5) mm and turned by 1 deg, the
// Gauss–Newton step's linear model predicts the sum of squared residuals after the step to 10 %,
// and the step takes away most of them. A wrong sign or a missing term in one of the six
// derivatives predicts a fall that does not come.
TEST(ImageEdgeLines, TheLinearModelPredictsTheResidualsAfterAStep)
{
	const Pair p;
	const SightedSamples samples(edgeSamplesOf(p.box, 3), &p.occ);
	const Eigen::Isometry3d start =
	    Eigen::Translation3d(1.2, -0.9, 0.5) * boxPose() *
	    Eigen::AngleAxisd(M_PI / 180, Eigen::Vector3d(1, 1, 1).normalized());
	const Eigen::Vector3d c_L = start.translation();
	const EdgeLineTerms t = p.images.edgeLines(samples, start, c_L);
	ASSERT_GE(t.n, 200);
	const Eigen::Matrix<double, 6, 1> d = -t.H.ldlt().solve(t.g);
	const double predicted = t.r2 + t.g.dot(d);  // r2 + 2 g·d + dᵀHd with H d = −g
	const EdgeLineTerms after = p.images.edgeLines(samples, stepped(start, c_L, d), c_L);
	EXPECT_NEAR(after.r2, predicted, 0.1 * predicted) << t.r2;
	EXPECT_LT(after.r2 / after.n, 0.25 * t.r2 / t.n);
}

// From a pose shifted by 2.5 mm and turned by 2 deg, the refinement fits the drawn edges better
// than the drawn pose itself does (lower chamfer cost: the drawing's edges are not exactly where
// the model projects) and lands within a pixel of it across the view (650 mm / 700 px, about
// 0.9 mm) and within 2 deg. Depth, which a 120 mm baseline resolves least, is not asked.
TEST(ImageEdgeLines, RefinementFitsTheEdgesAndLandsWithinAPixelAcrossTheView)
{
	const Pair p;
	const Eigen::Isometry3d start = Eigen::Translation3d(2.5, -2, 1.5) * boxPose() *
	                                Eigen::AngleAxisd(2 * M_PI / 180, Eigen::Vector3d::UnitX());
	const SightedSamples samples(edgeSamplesOf(p.box, 3), &p.occ);
	const Eigen::Isometry3d T = p.images.refine(samples, start, upAxisPoints(p.box));
	EXPECT_LE(p.images.score(samples, T).cost, p.images.score(samples, boxPose()).cost);
	const Eigen::Vector3d error = T.translation() - boxPose().translation();
	EXPECT_LT(error.head<2>().norm(), 650 / test::kFocal_px) << error.transpose();
	EXPECT_LT(test::rotationErrorDeg(T, boxPose()), 2.0);
}

// The reach is measured at the given point: a turn about another point moves it too.
TEST(ImageEdgeLines, ReachBoundsTheMoveOfThePointAndTheTurn)
{
	const Eigen::Isometry3d start = boxPose();
	const Eigen::Vector3d a_O(0, 0, 20);
	const auto moved = [&](double mm)
	{ return Eigen::Isometry3d(Eigen::Translation3d(0, mm, 0) * start); };
	const auto turned = [&](double deg, const Eigen::Vector3d& about_O)
	{
		return Eigen::Isometry3d(start * Eigen::Translation3d(about_O) *
		                         Eigen::AngleAxisd(deg * M_PI / 180, Eigen::Vector3d::UnitZ()) *
		                         Eigen::Translation3d(-about_O));
	};
	EXPECT_TRUE(withinRefinementReach(moved(kRefinementReach_mm - 0.1), start, a_O));
	EXPECT_FALSE(withinRefinementReach(moved(kRefinementReach_mm + 0.1), start, a_O));
	EXPECT_TRUE(withinRefinementReach(turned(kRefinementReach_deg - 0.1, a_O), start, a_O));
	EXPECT_FALSE(withinRefinementReach(turned(kRefinementReach_deg + 0.1, a_O), start, a_O));
	// 10 deg about a point 200 mm away moves a_O by about 35 mm
	EXPECT_FALSE(withinRefinementReach(turned(10, a_O + Eigen::Vector3d(200, 0, 0)), start, a_O));
}

// The local search takes a kept step's terms from the samples its score found on edges
// (EdgeImage::count's AlignedSamples): they are the terms of a walk over the samples, to the bit,
// at poses around the drawn one (some samples hidden, some beyond the truncation). A sample left
// out, or one the walk skips (occluded, off its edge's direction), changes them.
TEST(ImageEdgeLines, TermsFromACountsAlignedSamplesAreTheWalksToTheBit)
{
	const Pair p;
	const SightedSamples samples(edgeSamplesOf(p.box, 3), &p.occ);
	const double truncate_px = p.images.options().truncate_px;
	int compared = 0;
	for (int k = 0; k < 12; ++k)
	{
		const double s = (k - 6) / 3.0;
		const Eigen::Isometry3d T =
		    Eigen::Translation3d(1.5 * s, -s, 0.5 * s) * boxPose() *
		    Eigen::AngleAxisd(3 * s * M_PI / 180, Eigen::Vector3d(1, -2, 1).normalized());
		const Eigen::Vector3d c_L = T.translation();
		for (int i = 0; i < 2; ++i)
		{
			const EdgeImage& image = p.images.image(i);
			const auto limbs = image.limbsSeen(samples, T);
			std::vector<AlignedSample> aligned;
			ASSERT_TRUE(image.count(samples, T, limbs, truncate_px, nullptr, &aligned));
			EdgeLineTerms from_count, from_walk;
			image.addEdgeLines(aligned, c_L, truncate_px, from_count);
			image.addEdgeLines(samples, T, limbs, c_L, truncate_px, from_walk);
			EXPECT_GT(from_walk.n, 50);
			EXPECT_EQ(from_count.n, from_walk.n);
			EXPECT_TRUE(from_count.H == from_walk.H) << k << " " << i;
			EXPECT_TRUE(from_count.g == from_walk.g) << k << " " << i;
			EXPECT_EQ(from_count.r2, from_walk.r2);
			++compared;
		}
	}
	EXPECT_EQ(compared, 24);
}
