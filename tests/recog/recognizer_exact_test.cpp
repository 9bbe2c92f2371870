#include "recog_test_util.h"

#include <mrolr/recog/Recognizer.h>
#include <mrolr/sim/SyntheticObjects.h>
#include <mrolr/sim/SyntheticScene.h>

#include <gtest/gtest.h>

using namespace mrolr::recog;
using namespace mrolr::sim;

namespace
{
Eigen::Isometry3d somePose(int k)
{
	return tablePose(37.0 * k + 11, 25 + 3 * (k % 4),
	                 Eigen::Vector3d(40 - 10 * k, -80, 700 + 15 * k));
}
}  // namespace

// Every lab object carried by a known pose into an otherwise empty scene is found at the first
// level with the exact pose.
TEST(RecognizerExact, EveryObjectFoundWithExactPose)
{
	const auto objects = makeLabObjects();
	const auto opts = RecognitionOptions::defaults();
	for (size_t k = 0; k < objects.size(); ++k)
	{
		const auto T = somePose(static_cast<int>(k));
		const auto scene = placeInScene(objects[k], T);
		const Recognizer rec(objects[k], opts);
		const auto r = rec.recognize(scene);
		ASSERT_TRUE(r.found) << objects[k].name;
		EXPECT_EQ(r.level, 1) << objects[k].name;
		EXPECT_EQ(r.origin, Origin::Clique);
		EXPECT_NEAR(r.score, 1.0, 1e-9) << objects[k].name;
		EXPECT_LT((r.T_OinS.matrix() - T.matrix()).cwiseAbs().maxCoeff(), 1e-6) << objects[k].name;
	}
}

// The exact pose survives clutter: the other nine objects placed elsewhere in the same scene.
TEST(RecognizerExact, ExactPoseAmongTheOtherObjects)
{
	const auto objects = makeLabObjects();
	const auto opts = RecognitionOptions::defaults();
	mrolr::model::WireFrame scene;
	std::vector<Eigen::Isometry3d> poses;
	for (size_t k = 0; k < objects.size(); ++k)
	{
		poses.push_back(tablePose(29.0 * k, 30, Eigen::Vector3d(-500 + 110.0 * k, -100, 800)));
		appendWireFrame(scene, placeInScene(objects[k], poses.back()));
	}
	for (size_t k = 0; k < objects.size(); ++k)
	{
		const auto r = Recognizer(objects[k], opts).recognize(scene);
		ASSERT_TRUE(r.found) << objects[k].name;
		EXPECT_LT((r.T_OinS.matrix() - poses[k].matrix()).cwiseAbs().maxCoeff(), 1e-6)
		    << objects[k].name;
	}
}
