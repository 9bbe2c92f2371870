#pragma once
/** The stereo calibration of the BiSight head's ideal cameras at given joint angles (thesis 4.2,
 * eqs 4.22–4.23): both cameras share the head's pinhole intrinsics (no distortion) and the
 * left-to-right transform follows from T_LinC0 and T_RinC0. Used for the simulator's renders, whose
 * cameras are exactly the head model, and wherever the head's own calibration stands in for a
 * checkerboard calibration. */

#include <mrolr/geometry/BiSightHead.h>
#include <mrolr/stereo/StereoCalibration.h>

namespace mrolr::stereo
{
/** Calibration (OpenCV conventions, mm) of the head's cameras with the joints at @p angles. */
StereoCalibration calibrationFromHead(
	const geometry::BiSightHead& head, const geometry::HeadAngles& angles);

}  // namespace mrolr::stereo
