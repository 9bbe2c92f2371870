// The memo of a search's refinements (RefineMemo, ImageVerifier::refine): a start on a circle of
// yaws already swept takes it and lands where its own sweep would have taken it; a start off it
// sweeps its own.
#include "drawn_box_pair.h"
#include "recog_test_util.h"

#include <mrolr/recog/images/RefineMemo.h>

#include <gtest/gtest.h>

#include <cmath>

using namespace mrolr::recog;
using test::boxPose;
using test::Pair;

namespace
{
/** The first refinement's start: off the drawn pose by 2.5 mm and 2 deg. */
Eigen::Isometry3d firstStart()
{
	return Eigen::Translation3d(2.5, -2, 1.5) * boxPose() *
	       Eigen::AngleAxisd(2 * M_PI / 180, Eigen::Vector3d::UnitX());
}

Eigen::Isometry3d turned(const Eigen::Isometry3d& T, const Eigen::Vector3d& a_O, double deg)
{
	return T * Eigen::Translation3d(a_O) *
	       Eigen::AngleAxisd(deg * M_PI / 180, Eigen::Vector3d::UnitZ()) *
	       Eigen::Translation3d(-a_O);
}
}  // namespace

// The box is swept about two axes (its button's centre and its length-weighted centre). A start
// turned by six sweep steps (30 deg) about the first has that axis's circle already: it takes
// it, sweeps the other, and lands where a refinement without the memo lands (the same poses
// swept, in another order).
TEST(RefineMemo, AStartOnASweptCircleTakesItAndLandsWhereItsOwnSweepWould)
{
	const Pair p;
	const SightedSamples samples(edgeSamplesOf(p.box, 3), &p.occ);
	const auto axes_O = upAxisPoints(p.box);
	ASSERT_EQ(axes_O.size(), 2u);
	RefineMemo memo;
	p.images.refine(samples, firstStart(), axes_O, &memo);
	ASSERT_EQ(memo.circles.size(), 2u);
	const Eigen::Isometry3d start = turned(firstStart(), axes_O[0], 30);
	const Eigen::Isometry3d alone = p.images.refine(samples, start, axes_O);
	const Eigen::Isometry3d with_memo = p.images.refine(samples, start, axes_O, &memo);
	EXPECT_EQ(memo.circles_reused, 1);
	EXPECT_EQ(memo.circles.size(), 3u);
	EXPECT_LT((with_memo.translation() - alone.translation()).norm(), 0.01);
	EXPECT_LT(test::rotationErrorDeg(with_memo, alone), 0.01);
}

// Half a sweep step off the circle, or 0.5 mm beside it, a start sweeps its own circles.
TEST(RefineMemo, AStartOffASweptCircleSweepsItsOwn)
{
	const Pair p;
	const SightedSamples samples(edgeSamplesOf(p.box, 3), &p.occ);
	const auto axes_O = upAxisPoints(p.box);
	RefineMemo memo;
	p.images.refine(samples, firstStart(), axes_O, &memo);
	p.images.refine(samples, turned(firstStart(), axes_O[0], 32.5), axes_O, &memo);
	p.images.refine(samples, Eigen::Translation3d(0.5, 0, 0) * firstStart(), axes_O, &memo);
	EXPECT_EQ(memo.circles_reused, 0);
	EXPECT_EQ(memo.circles.size(), 6u);
}
