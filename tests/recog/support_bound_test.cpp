#include <mrolr/recog/Recognizer.h>
#include <mrolr/recog/SupportBound.h>
#include <mrolr/sim/SyntheticObjects.h>
#include <mrolr/sim/SyntheticScene.h>
#include <mrolr/recog/Verification.h>

#include <gtest/gtest.h>

#include <random>

using namespace mrolr::recog;
using namespace mrolr::sim;

namespace
{
constexpr double kBeta = 3, kTheta = 3 * M_PI / 180;

SceneNoise noisy()
{
	SceneNoise n;
	n.endpoint_sigma_mm = 0.7, n.fragment_probability = 0.3, n.missing_fraction = 0.15;
	return n;
}

/** A random pose near the scene: the model's centroid within 150 mm of a scene feature. */
Eigen::Isometry3d poseNear(const std::vector<Feature>& scene, std::mt19937& rng)
{
	std::uniform_real_distribution<double> u(-1, 1);
	Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
	T.linear() = Eigen::Quaterniond(Eigen::Vector4d(u(rng), u(rng), u(rng), u(rng)).normalized())
	                 .toRotationMatrix();
	const auto& f = scene[static_cast<size_t>(std::abs(u(rng)) * (scene.size() - 1))];
	T.translation() = f.m + 150 * Eigen::Vector3d(u(rng), u(rng), u(rng));
	return T;
}
}  // namespace

// The bound is above the verified support of the true pose and of random poses, in cluttered,
// noisy scenes, for every lab object (it must never skip a level that could verify).
TEST(SupportBound, BoundsTheVerifiedSupportOfAnyPose)
{
	const auto objects = makeLabObjects();
	std::mt19937 rng(7);
	for (size_t k = 0; k < objects.size(); ++k)
	{
		const ModelTable model(objects[k], 12, 7);
		const SupportBound bound(model, kBeta, kTheta);
		const auto ts = makeTableScene(objects, static_cast<int>(k), 3, noisy(), 50 + k);
		const auto scene = featuresOf(ts.scene);
		const double b = bound.supportBound_mm(scene);
		EXPECT_GE(b + 1e-9, verifyPose(model, scene, ts.T_OinS, kBeta, kTheta).supported_mm);
		for (int i = 0; i < 50; ++i)
			EXPECT_GE(b + 1e-9,
			          verifyPose(model, scene, poseNear(scene, rng), kBeta, kTheta).supported_mm);
	}
}

// The focus bound holds for the poses that put the focus on its scene match: the true pose with
// each model feature's own image as the focus match.
TEST(SupportBound, FocusBoundHoldsAtTheTruePose)
{
	const auto objects = makeLabObjects();
	for (size_t k = 0; k < objects.size(); ++k)
	{
		const ModelTable model(objects[k], 12, 7);
		const SupportBound bound(model, kBeta, kTheta);
		const Eigen::Isometry3d T = makeTableScene(objects, static_cast<int>(k), 0, {}, 9).T_OinS;
		const auto scene = featuresOf(placeInScene(objects[k], T));
		const double supported = verifyPose(model, scene, T, kBeta, kTheta).supported_mm;
		for (size_t f = 0; f < model.features().size(); ++f)
			EXPECT_GE(bound.focusSupportBound_mm(scene, f, scene[f], 2) + 1e-9, supported)
			    << objects[k].name << " focus " << f;
	}
}

// A scene with too little nearby length for the model: every level is skipped, "not found";
// with the skips off the same answer (the search finds nothing either).
TEST(SupportBound, SparseSceneSkipsEveryLevel)
{
	const auto objects = makeLabObjects();
	const auto cube = objects[0];
	mrolr::model::WireFrame scene;
	scene.frame = mrolr::model::WireFrameFrame::LeftCamera;
	for (int i = 0; i < 4; ++i)  // short segments 400 mm apart
		scene.lines.push_back({i + 1, {400.0 * i, 0, 800}, {400.0 * i + 30, 0, 800}});
	auto opts = RecognitionOptions::defaults();
	const auto r = Recognizer(cube, opts).recognize(scene);
	EXPECT_FALSE(r.found);
	EXPECT_EQ(r.levels_skipped, static_cast<int>(opts.levels.size()));
	opts.skip_hopeless_levels = false;
	const auto r2 = Recognizer(cube, opts).recognize(scene);
	EXPECT_FALSE(r2.found);
	EXPECT_EQ(r2.levels_skipped, 0);
}

// Skipping never changes an answer: the synthetic table scenes give the same found flags and poses
// with and without it.
TEST(SupportBound, SkippingKeepsTheAnswers)
{
	const auto objects = makeLabObjects();
	auto with = RecognitionOptions::defaults(), without = with;
	without.skip_hopeless_levels = false;
	for (size_t k = 0; k < objects.size(); k += 3)
	{
		const auto ts = makeTableScene(objects, static_cast<int>(k), 3, noisy(), 300 + k);
		for (size_t m = 0; m < objects.size(); m += 2)
		{
			const auto a = Recognizer(objects[m], with).recognize(ts.scene);
			const auto b = Recognizer(objects[m], without).recognize(ts.scene);
			EXPECT_EQ(a.found, b.found) << objects[m].name;
			if (a.found && b.found)
			{
				EXPECT_TRUE(a.T_OinS.isApprox(b.T_OinS, 1e-9)) << objects[m].name;
			}
		}
	}
}
