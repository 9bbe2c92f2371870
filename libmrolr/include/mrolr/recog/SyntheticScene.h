#pragma once
/** Synthetic scene wire-frames with exact ground truth: a model carried by a known pose, seen from
 * one side (back features hidden), with missing segments, fragmented lines, endpoint noise,
 * arbitrary endpoint order and normal sign, and clutter from other objects. Millimetres. */

#include <mrolr/model/WireFrame.h>

#include <Eigen/Geometry>

#include <random>

namespace mrolr::recog
{
struct SceneNoise
{
	double endpoint_sigma_mm = 0;  ///< Gaussian noise on line endpoints and conic centres (mm)
	double fragment_probability = 0;  ///< chance that a line is cut in two with a gap
	double missing_fraction = 0;  ///< fraction of the (visible) features dropped at random
	bool hide_back_side = false;   ///< drop features on the far side from the camera (along +z)
	double flip_probability = 0.5;  ///< chance of swapping a line's endpoints / a conic's normal
};

/** @p wf with every element carried by T (frame of the result: LeftCamera). */
model::WireFrame transformWireFrame(const model::WireFrame& wf, const Eigen::Isometry3d& T);

/** Applies @p noise to @p wf (already in scene coordinates); @p visible_fraction receives the
 * fraction of the model's line+arc length that survives hiding and dropping. */
model::WireFrame corruptScene(
	const model::WireFrame& wf, const SceneNoise& noise, std::mt19937& rng,
	double* visible_fraction = nullptr);

/** Appends the elements of @p b to @p a with fresh ids. */
void appendWireFrame(model::WireFrame& a, const model::WireFrame& b);

/** A pose of an object standing on a table seen by a camera looking along +z: rotation @p yaw_deg
 * about the object's vertical, tilt @p tilt_deg, placed at @p p_mm. */
Eigen::Isometry3d tablePose(double yaw_deg, double tilt_deg, const Eigen::Vector3d& p_mm);

}  // namespace mrolr::recog
