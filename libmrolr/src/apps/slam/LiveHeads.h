#pragma once
// The heads mrolr-slam --live can drive: the synthetic textured-point head (vision area) or the
// simulator's rendered lab (sim::SimHead over sim::StereoRenderer), both told the true vehicle
// pose.
#include <mrolr/vision/StereoHeadDevice.h>
#include <mrolr/vision/SyntheticWorld.h>
#include <mrolr/world/World.h>

#include <mrpt/img/CImage.h>
#include <Eigen/Core>
#include <opencv2/core.hpp>

#include <memory>
#include <string>

namespace mrolr::apps
{
/** A StereoHeadDevice on a vehicle whose true pose the simulation sets. */
class LiveHead : public vision::StereoHeadDevice
{
 public:
	virtual void setVehicle(const Eigen::Vector3d& x_true) = 0;
	/** True when textures lie on the world's surfaces (the rendered lab); false when each landmark
	 * is a sprite facing the camera (synthetic), whose off-centre pixels are no fixed 3D points. */
	virtual bool rendersSurfaces() const = 0;
};

/** An 8-bit greyscale copy of @p img (colour images are converted). */
cv::Mat toGray(const mrpt::img::CImage& img);

/** "synthetic" (textured points, @p texture_px, @p noise_grey, @p seed) or "lab" (CFBORender of the
 * world's room, patches, tables and objects); throws std::invalid_argument for another name. */
std::unique_ptr<LiveHead> makeLiveHead(const std::string& kind, const world::World& w,
                                       const geometry::BiSightHead& head, int texture_px,
                                       double noise_grey, unsigned seed);

}  // namespace mrolr::apps
