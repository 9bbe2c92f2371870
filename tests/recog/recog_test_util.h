#pragma once
/** Shared helpers of the recog tests: default options, pose errors. */

#include <mrolr/recog/RecognitionOptions.h>
#include <mrolr/sim/SyntheticScene.h>
#include <mrolr/recog/TransformCluster.h>

#include <Eigen/Geometry>

#include <random>

namespace mrolr::recog::test
{
inline double rotationErrorDeg(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b)
{
	return rotationDistanceDeg(a.linear(), b.linear());
}

/** A pose of uniformly random rotation and translation within ±500 mm on each axis. */
inline Eigen::Isometry3d randomPose(std::mt19937& rng)
{
	std::uniform_real_distribution<> u(-1, 1);
	Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
	T.linear() = Eigen::Quaterniond(Eigen::Vector4d(u(rng), u(rng), u(rng), u(rng)).normalized())
	                 .toRotationMatrix();
	T.translation() = Eigen::Vector3d(u(rng), u(rng), u(rng)) * 500;
	return T;
}

/** Translation error at the model's origin (mm). */
inline double translationErrorMm(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b)
{
	return (a.translation() - b.translation()).norm();
}

/** The noise of the fixed synthetic table scenes: endpoint noise 0.7 mm, 30 % of lines fragmented,
 * 15 % missing, the far half hidden. */
inline sim::SceneNoise realisticNoise()
{
	sim::SceneNoise n;
	n.endpoint_sigma_mm = 0.7;
	n.fragment_probability = 0.3;
	n.missing_fraction = 0.15;
	n.hide_back_side = true;
	return n;
}

/** Calls @p trial(scene, seed) on the fixed synthetic table scenes of object @p k (6 seeds, 3
 * other objects) that show at least half of it; returns how many there were. */
template <class Trial>
int forEachVisibleTableScene(const std::vector<model::WireFrame>& objects, size_t k, Trial trial)
{
	int trials = 0;
	for (unsigned s = 0; s < 6; ++s)
	{
		const auto ts =
		    makeTableScene(objects, static_cast<int>(k), 3, realisticNoise(), 1000 * k + s);
		if (ts.visible_fraction < 0.5) continue;
		++trials;
		trial(ts, s);
	}
	return trials;
}

}  // namespace mrolr::recog::test
