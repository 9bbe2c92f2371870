#include "KnownAcquisition.h"

#include <mrolr/geometry/Frames.h>
#include <mrolr/slam/HeadMeasurement.h>
#include <mrolr/vision/Fixation.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace mrolr::apps
{
namespace
{
/** The patch to store for the landmark the head was aimed at: the best corner near the image
 * centre when @p pick_corner, else the centre itself. */
cv::Mat pickPatch(const vision::StereoImages& im, const geometry::BiSightHead& head,
                  bool pick_corner, const vision::VisionOptions& o)
{
	const auto& cam = head.camera();
	const Eigen::Vector2d centre(cam.u0_px, cam.v0_px);
	const int side = o.known_search_box_px;
	const cv::Rect box(int(std::lround(cam.u0_px)) - side / 2,
	                   int(std::lround(cam.v0_px)) - side / 2, side, side);
	const auto corner = pick_corner && side > 1
	                        ? vision::bestCornerInBox(im.left, box, o.patch_size_px,
	                                                  o.min_corner_eigenvalue)
	                        : std::nullopt;
	return vision::extractPatch(im.left, corner ? corner->uv : centre, o.patch_size_px);
}

vision::KnownFeature acquireOne(const world::Landmark& l, LiveHead& device,
                                const geometry::BiSightHead& head, const SlamSetup& s,
                                const Eigen::Vector3d& x0)
{
	const Eigen::Isometry3d T_C0inW = geometry::T_C0inW(x0, s.bisight.head_height_m);
	const Eigen::Vector3d c_inC0 = slam::pointInHead(x0, l.p_LinW, s.slam.head.constants);
	device.moveTo(head.fixate(c_inC0));
	const cv::Mat patch = pickPatch(device.grab(), head, device.rendersSurfaces(), s.vision);
	const vision::FixationResult r = vision::fixateOnPatch(device, head, patch, c_inC0, s.vision);
	if (!r.locked) throw std::runtime_error("known feature '" + l.name + "': " + r.failure);
	// The world's landmark only aimed the head, as an operator would; what is stored is the
	// robot's own triangulation of the locked patch (thesis 5.6.2), never the world's position.
	return {l.name, T_C0inW * r.p_GinC0, patch};
}
}  // namespace

std::vector<vision::KnownFeature> acquireKnown(const world::World& w, LiveHead& device,
                                               const geometry::BiSightHead& head,
                                               const SlamSetup& s, const Eigen::Vector3d& x0,
                                               const std::vector<std::string>& names)
{
	for (const auto& n : names)
		if (!w.findLandmark(n))
			throw std::runtime_error(w.path + ": no landmark named '" + n + "'");
	std::vector<vision::KnownFeature> out;
	for (const auto& l : w.landmarks)
	{
		const bool wanted =
		    names.empty() ? l.known : std::count(names.begin(), names.end(), l.name) > 0;
		if (wanted) out.push_back(acquireOne(l, device, head, s, x0));
	}
	return out;
}

}  // namespace mrolr::apps
