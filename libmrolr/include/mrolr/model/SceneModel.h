#pragma once
/** Scene wire-frames from stereo (thesis 4.3.2.3, 6.3): the segments reconstructed by
 * stereo::reconstructScene as a model::WireFrame in the left camera frame L, and the same model
 * moved into the head frame C0 given the head angles (thesis eqs 4.22, 4.41). */

#include <mrolr/geometry/BiSightHead.h>
#include <mrolr/model/WireFrame.h>
#include <mrolr/stereo/SceneReconstruction.h>

#include <Eigen/Geometry>

namespace mrolr::model
{
/** The reconstructed scene as a wire-frame in frame left_camera (mm), ids 1, 2, … in order. */
WireFrame sceneToWireFrame(const stereo::StereoScene& scene);

/** Applies the rigid transform p_to = T_mm · p_from (translation in mm) to every feature and the
 * grasp, and relabels the frame. */
WireFrame transformWireFrame(const WireFrame& wf, const Eigen::Isometry3d& T_mm, WireFrameFrame to);

/** A left-camera wire-frame moved into C0 with the head at @p angles (T_LinC0, metres in the
 * geometry library, converted to mm). Throws std::invalid_argument unless wf is in left_camera. */
WireFrame leftCameraToC0(const WireFrame& wf_L, const geometry::BiSightHead& head,
                         const geometry::HeadAngles& angles);

}  // namespace mrolr::model
