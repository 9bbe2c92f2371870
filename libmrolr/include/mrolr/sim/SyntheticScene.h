#pragma once
/** Synthetic scene wire-frames with exact ground truth: a model carried by a known pose, seen from
 * one side (back features hidden), with missing segments, fragmented lines, endpoint noise,
 * arbitrary endpoint order and normal sign, and clutter from other objects. Millimetres. */

#include <mrolr/model/SceneModel.h>
#include <mrolr/model/WireFrame.h>

#include <Eigen/Geometry>

#include <random>
#include <vector>

namespace mrolr::sim
{
struct SceneNoise
{
	double endpoint_sigma_mm = 0;     ///< Gaussian noise on line endpoints and conic centres (mm)
	double fragment_probability = 0;  ///< chance that a line is cut in two with a gap
	double missing_fraction = 0;      ///< fraction of the (visible) features dropped at random
	bool hide_back_side = false;      ///< drop features on the far side from the camera (along +z)
	double flip_probability = 0.5;    ///< chance of swapping a line's endpoints / a conic's normal
};

/** @p wf carried by T_OinS into the left-camera frame (model::transformWireFrame). */
inline model::WireFrame placeInScene(const model::WireFrame& wf, const Eigen::Isometry3d& T_OinS)
{
	return model::transformWireFrame(wf, T_OinS, model::WireFrameFrame::LeftCamera);
}

/** Applies @p noise to @p wf (already in scene coordinates); @p visible_fraction receives the
 * fraction of the model's line+arc length that survives hiding and dropping. */
model::WireFrame corruptScene(const model::WireFrame& wf, const SceneNoise& noise,
                              std::mt19937& rng, double* visible_fraction = nullptr);

/** Appends the elements of @p b to @p a with fresh ids. */
void appendWireFrame(model::WireFrame& a, const model::WireFrame& b);

/** A pose of an object standing on a table seen by a camera looking along +z: rotation @p yaw_deg
 * about the object's vertical, tilt @p tilt_deg, placed at @p p_mm. */
Eigen::Isometry3d tablePose(double yaw_deg, double tilt_deg, const Eigen::Vector3d& p_mm);

/** A table scene with its ground truth. */
struct TableScene
{
	model::WireFrame scene;  ///< frame LeftCamera, mm
	int target = -1;         ///< index of the target object, -1 when absent
	Eigen::Isometry3d T_OinS = Eigen::Isometry3d::Identity();  ///< true pose of the target
	double visible_fraction = 0;  ///< fraction of the target's length left in the scene
};

/** Objects on a table 700–1000 mm in front of the camera, 260 mm apart along x: the target
 * @p objects[target] (none when target < 0) and @p clutter others chosen at random, each at a
 * random yaw, a tilt of 20–40° (seen from above) and corrupted by @p noise. Deterministic in @p
 * seed. */
TableScene makeTableScene(const std::vector<model::WireFrame>& objects, int target, int clutter,
                          const SceneNoise& noise, unsigned seed);

}  // namespace mrolr::sim
