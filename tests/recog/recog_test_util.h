#pragma once
/** Shared helpers of the recog tests: default options, pose errors. */

#include <mrolr/recog/RecognitionOptions.h>
#include <mrolr/recog/TransformCluster.h>

#include <Eigen/Geometry>

namespace mrolr::recog::test
{
inline double rotationErrorDeg(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b)
{
	return rotationDistanceDeg(a.linear(), b.linear());
}

/** Translation error at the model's origin (mm). */
inline double translationErrorMm(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b)
{
	return (a.translation() - b.translation()).norm();
}

}  // namespace mrolr::recog::test
