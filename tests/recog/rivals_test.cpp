// Which model explains a place better (recog/Rivals.h): properties of betterExplained.
#include <gtest/gtest.h>
#include <mrolr/recog/Rivals.h>

#include <cmath>

namespace
{
using mrolr::recog::betterExplained;
using mrolr::recog::Footprint;
using mrolr::recog::PlacedAnswer;
using mrolr::recog::RecognitionResult;

/** A cylinder's rims: conics of radius @p r_mm at z = 0 and @p h_mm, one side line. */
mrolr::model::WireFrame cylinder(double r_mm, double h_mm)
{
	mrolr::model::WireFrame wf;
	for (double z : {0.0, h_mm})
	{
		mrolr::model::Conic3 c;
		c.centre = {0, 0, z};
		c.a = c.b = r_mm;
		c.t2 = 2 * M_PI;
		wf.conics.push_back(c);
	}
	mrolr::model::Line3 side;
	side.p1 = {r_mm, 0, 0};
	side.p2 = {r_mm, 0, h_mm};
	wf.lines.push_back(side);
	return wf;
}

RecognitionResult found(const Eigen::Vector3d& p_S, double image_score)
{
	RecognitionResult r;
	r.found = true;
	r.image_score = image_score;
	r.T_OinS = Eigen::Translation3d(p_S) * Eigen::Isometry3d::Identity();
	return r;
}

const Eigen::Vector3d kUp = Eigen::Vector3d::UnitZ();
}  // namespace

TEST(Rivals, FootprintReachesTheWidestRim)
{
	const Footprint f = mrolr::recog::footprintOf(cylinder(33, 120));
	EXPECT_NEAR(f.radius_mm, 33, 0.01);
	EXPECT_NEAR(f.centre_O.head<2>().norm(), 0, 1e-9);  // on the axis, not pulled by the side line
	EXPECT_NEAR(f.centre_O.z(), 60, 1e-9);
}

TEST(Rivals, AHigherScoreAtTheSamePlaceExplainsItBetter)
{
	const Footprint can = mrolr::recog::footprintOf(cylinder(33, 120));
	const Footprint bottle = mrolr::recog::footprintOf(cylinder(35, 250));
	const RecognitionResult target = found({500, 0, 0}, 0.66);
	const RecognitionResult there = found({510, 5, 0}, 0.80);
	const RecognitionResult weaker = found({500, 0, 0}, 0.60);
	EXPECT_EQ(betterExplained({&target, can}, {{&weaker, bottle}, {&there, bottle}}, kUp), 1u);
	EXPECT_FALSE(betterExplained({&target, can}, {{&weaker, bottle}}, kUp));
}

TEST(Rivals, ARivalElsewhereOrNotFoundIsNoRival)
{
	const Footprint can = mrolr::recog::footprintOf(cylinder(33, 120));
	const RecognitionResult target = found({500, 0, 0}, 0.66);
	const RecognitionResult beside = found({500, 80, 0}, 0.9);  // touching, not overlapping
	RecognitionResult absent = found({500, 0, 0}, 0.9);
	absent.found = false;
	EXPECT_FALSE(betterExplained({&target, can}, {{&beside, can}, {&absent, can}}, kUp));
}

TEST(Rivals, OnlyTheOffsetAcrossUpCounts)
{
	// a rival found 200 mm above the target (a tall object's top taken for a short one) still
	// takes its place on the table
	const Footprint can = mrolr::recog::footprintOf(cylinder(33, 120));
	const RecognitionResult target = found({500, 0, 0}, 0.66);
	const RecognitionResult above = found({500, 0, 200}, 0.7);
	EXPECT_EQ(betterExplained({&target, can}, {{&above, can}}, kUp), 0u);
	EXPECT_FALSE(betterExplained({&target, can}, {{&above, can}}, Eigen::Vector3d::UnitX()));
}

TEST(Rivals, NothingToCompareWithoutAnImageScore)
{
	const Footprint can = mrolr::recog::footprintOf(cylinder(33, 120));
	RecognitionResult target = found({500, 0, 0}, 0.66);
	const RecognitionResult there = found({500, 0, 0}, 0.9);
	target.image_score.reset();
	EXPECT_FALSE(betterExplained({&target, can}, {{&there, can}}, kUp));
	target = found({500, 0, 0}, 0.66);
	target.found = false;
	EXPECT_FALSE(betterExplained({&target, can}, {{&there, can}}, kUp));
}
