// The upright prior and the expected-visible verification score (SelfOcclusion.h): what a camera
// sees of a box, and the synthetic table scenes searched with the scene's up direction.
#include "recog_test_util.h"

#include <mrolr/recog/Recognizer.h>
#include <mrolr/recog/SelfOcclusion.h>
#include <mrolr/sim/SyntheticObjects.h>
#include <mrolr/sim/SyntheticScene.h>
#include <mrolr/recog/WireFrameBuilder.h>

#include <gtest/gtest.h>

#include <cmath>

using namespace mrolr::recog;
using namespace mrolr::sim;
using test::realisticNoise;

namespace
{
/** makeTableScene tilts every object 20–40° towards the camera: the room's up is the camera's
 * +y turned by the mean tilt, 30°, about x (tablePose). */
Eigen::Vector3d tableUp()
{
	return Eigen::AngleAxisd(30 * M_PI / 180, Eigen::Vector3d::UnitX()) * Eigen::Vector3d::UnitY();
}

double angleDeg(const Eigen::Matrix3d& a, const Eigen::Matrix3d& b)
{
	return Eigen::AngleAxisd(a.transpose() * b).angle() * 180 / M_PI;
}
}  // namespace

TEST(SelfOcclusion, CameraSeesTheFrontOfABoxAndNotItsBack)
{
	const auto features =
	    featuresOf(WireFrameBuilder("box").box({-50, -50, -50}, {50, 50, 50}).build());
	const SelfOcclusion occ(features);
	const auto seen = occ.visibleFractions({0, 0, -1000});  // on the -z axis, looking at -z face
	int front = 0, back = 0, side = 0;
	for (size_t i = 0; i < features.size(); ++i)
	{
		const auto& f = features[i];
		const double z1 = f.p1.z(), z2 = f.p2.z();
		if (z1 == -50 && z2 == -50)
		{
			++front;
			EXPECT_DOUBLE_EQ(seen[i], 1.0);
		}
		else if (z1 == 50 && z2 == 50)
		{
			++back;
			EXPECT_DOUBLE_EQ(seen[i], 0.0);
		}
		else
		{
			++side;
			EXPECT_GT(seen[i], 0.0);
			EXPECT_LT(seen[i], 1.0);
		}
	}
	EXPECT_EQ(front, 4);
	EXPECT_EQ(back, 4);
	EXPECT_EQ(side, 4);
	// from a corner direction every edge touching the nearest corner is seen whole
	const auto corner = occ.visibleFractions({-1000, -1000, -1000});
	for (size_t i = 0; i < features.size(); ++i)
		if (features[i].p1.isApprox(Eigen::Vector3d(-50, -50, -50)) ||
		    features[i].p2.isApprox(Eigen::Vector3d(-50, -50, -50)))
		{
			EXPECT_DOUBLE_EQ(corner[i], 1.0);
		}
}

TEST(UprightPrior, ASceneSeenUpsideDownFindsNothingUpright)
{
	const auto objects = makeLabObjects();
	const Recognizer rec(objects[1], RecognitionOptions::defaults());
	const auto ts = makeTableScene(objects, 1, 2, realisticNoise(), 77);
	const Eigen::Vector3d up = tableUp(), down = -up;
	const auto r = rec.recognize(ts.scene, {up, std::nullopt, std::nullopt});
	ASSERT_TRUE(r.found);
	EXPECT_LT(angleDeg(r.T_OinS.linear(), ts.T_OinS.linear()), 10);
	const auto d = rec.recognize(ts.scene, {down, std::nullopt, std::nullopt});
	EXPECT_FALSE(d.found);  // the true pose is rejected, a turned-over one is not supported
	EXPECT_FALSE(rec.upright(ts.T_OinS, down));
	EXPECT_TRUE(rec.upright(ts.T_OinS, up));
}

// The synthetic table scenes of recognizer_accuracy_test, searched with the scene's up direction
// (upright prior, expected-visible score): the targets and no false positive hold too.
TEST(UprightPrior, TableScenesWithUpKeepTheTargetsAndNoFalsePositive)
{
	const auto objects = makeLabObjects();
	const auto opts = RecognitionOptions::defaults();
	ASSERT_TRUE(opts.verify_visible_only);
	const Eigen::Vector3d up = tableUp();
	int trials = 0, recognised = 0, false_positives = 0;
	for (size_t k = 0; k < objects.size(); ++k)
	{
		const Recognizer rec(objects[k], opts);
		trials += test::forEachVisibleTableScene(
		    objects, k,
		    [&](const TableScene& ts, unsigned)
		    {
			    const auto r = rec.recognize(ts.scene, {up, std::nullopt, std::nullopt});
			    recognised += r.found && angleDeg(r.T_OinS.linear(), ts.T_OinS.linear()) < 10 &&
			                  (r.T_OinS.translation() - ts.T_OinS.translation()).norm() < 30;
		    });
		auto others = objects;
		others.erase(others.begin() + static_cast<long>(k));
		for (unsigned s = 0; s < 3; ++s)
			false_positives +=
			    rec.recognize(
			           makeTableScene(others, -1, 4, realisticNoise(), 5000 + 10 * k + s).scene,
			           {up, std::nullopt, std::nullopt})
			        .found;
	}
	EXPECT_GE(static_cast<double>(recognised) / trials, 0.95);
	EXPECT_EQ(false_positives, 0);
}
