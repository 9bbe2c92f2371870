#pragma once
/** Pictures of a wire-frame (thesis 6.2's editor display): an orthographic PNG drawing with OpenCV
 * and a `.3Dscene` for MRPT's SceneViewer3D. */

#include <mrolr/model/WireFrame.h>

#include <mrpt/opengl/CSetOfObjects.h>

#include <opencv2/core.hpp>

#include <string>

namespace mrolr::model
{
/** Orthographic view: the viewer sits in direction (azimuth, elevation) from the model. For frame
 * object, up is z and azimuth is measured from x towards y; for left_camera and c0, up is y and
 * azimuth 0, elevation 0 is the camera's own view (looking along +z). */
struct DrawOptions
{
	int width_px = 800, height_px = 600;
	double azimuth_deg = 0, elevation_deg = 0;
	bool show_ids = true;
};

/** Default view of a frame: 30°/25° for objects, the camera's view otherwise. */
DrawOptions defaultDrawOptions(WireFrameFrame frame);

/** The model drawn in colour: lines blue, conics red, grasp green, ids in grey. */
cv::Mat drawWireFrame(const WireFrame& wf, const DrawOptions& options);

/** Writes drawWireFrame to a PNG; throws std::runtime_error if it cannot be written. */
void saveWireFramePng(const WireFrame& wf, const DrawOptions& options, const std::string& path);

/** The model as MRPT opengl lines, in metres (mm / 1000), conics as polylines. */
mrpt::opengl::CSetOfObjects::Ptr wireFrameObject(const WireFrame& wf);

/** Writes a `.3Dscene` holding the model and axes; throws std::runtime_error on failure. */
void saveWireFrameScene(const WireFrame& wf, const std::string& path);

}  // namespace mrolr::model
