#pragma once
/** The minimal view the vision pipeline needs of an active stereo head: move to joint angles, grab
 * a stereo pair. The simulated and serial heads of the hw/sim areas can be adapted to it; the
 * pipeline never asks which one it has. */

#include <mrolr/geometry/BiSightHead.h>

#include <opencv2/core.hpp>

namespace mrolr::vision
{
/** One stereo pair (8-bit greyscale) and the head angles it was taken at. */
struct StereoImages
{
	cv::Mat left, right;          ///< CV_8UC1, same size
	geometry::HeadAngles angles;  ///< radians, when the pair was grabbed
};

/** A pan–tilt–vergence stereo head that returns images (thesis 4.2.2, 5.3). */
class StereoHeadDevice
{
 public:
	virtual ~StereoHeadDevice() = default;
	/** Moves the joints to @p angles (radians) and returns when they have settled. Throws if an
	 * angle is beyond a joint limit. */
	virtual void moveTo(const geometry::HeadAngles& angles) = 0;
	/** The current joint angles, radians. */
	virtual geometry::HeadAngles angles() const = 0;
	/** A stereo pair taken at the current angles. */
	virtual StereoImages grab() = 0;
};

}  // namespace mrolr::vision
