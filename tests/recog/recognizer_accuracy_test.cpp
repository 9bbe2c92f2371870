#include "recog_test_util.h"

#include <mrolr/recog/Recognizer.h>
#include <mrolr/sim/SyntheticObjects.h>
#include <mrolr/sim/SyntheticScene.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>

using namespace mrolr::recog;
using namespace mrolr::sim;

namespace
{
double median(std::vector<double> v)
{
	if (v.empty()) return 0;
	std::sort(v.begin(), v.end());
	return v[v.size() / 2];
}
}  // namespace

using test::realisticNoise;

// The fixed set of synthetic table scenes: every lab object in 6 random poses among 3 other
// objects, noisy, fragmented, its far side hidden and some segments missing.
TEST(RecognizerAccuracy, TableScenesMeetTheIssueTargets)
{
	const auto objects = makeLabObjects();
	const auto opts = RecognitionOptions::defaults();
	int trials = 0, recognised = 0;
	std::vector<double> rot, trans;
	for (size_t k = 0; k < objects.size(); ++k)
	{
		const Recognizer rec(objects[k], opts);
		trials += test::forEachVisibleTableScene(
		    objects, k,
		    [&](const TableScene& ts, unsigned s)
		    {
			    const auto r = rec.recognize(ts.scene);
			    const double er = test::rotationErrorDeg(r.T_OinS, ts.T_OinS);
			    const double et = test::translationErrorMm(r.T_OinS, ts.T_OinS);
			    if (!r.found || er > 10 || et > 30)
			    {
				    std::printf(
				        "miss %s seed %u found %d level %d score %.2f rot %.1f trans %.1f "
				        "vis %.2f\n",
				        objects[k].name.c_str(), s, r.found, r.level.value_or(0), r.score, er, et,
				        ts.visible_fraction);
				    return;
			    }
			    ++recognised;
			    rot.push_back(er);
			    trans.push_back(et);
		    });
	}
	const double rate = static_cast<double>(recognised) / trials;
	std::printf("trials %d recognised %.3f median rot %.3f deg median trans %.3f mm\n", trials,
	            rate, median(rot), median(trans));
	EXPECT_GE(rate, 0.95);
	EXPECT_LT(median(rot), 2.0);
	EXPECT_LT(median(trans), 5.0);
}

// Absent objects: each object searched for in scenes made of four other objects is not found.
TEST(RecognizerAccuracy, AbsentObjectsAreNotFound)
{
	const auto objects = makeLabObjects();
	const auto opts = RecognitionOptions::defaults();
	int false_positives = 0;
	for (size_t k = 0; k < objects.size(); ++k)
	{
		const Recognizer rec(objects[k], opts);
		for (unsigned s = 0; s < 3; ++s)
		{
			auto others = objects;
			others.erase(others.begin() + static_cast<long>(k));
			const auto ts = makeTableScene(others, -1, 4, realisticNoise(), 5000 + 10 * k + s);
			const auto r = rec.recognize(ts.scene);
			if (r.found)
				std::printf("false positive %s seed %u level %d score %.2f\n",
				            objects[k].name.c_str(), s, r.level.value_or(0), r.score);
			false_positives += r.found;
		}
	}
	EXPECT_EQ(false_positives, 0);
}
