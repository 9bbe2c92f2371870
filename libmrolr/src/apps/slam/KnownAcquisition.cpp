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
const world::Patch* planeOf(const world::World& w, const std::string& name)
{
	for (const auto& p : w.patches)
		if (p.name == name) return &p;
	return nullptr;
}

/** Where the left ray of pixel @p uv meets the plane through @p c with normal @p n (all C0). */
Eigen::Vector3d onPlane(const geometry::BiSightHead& head, const geometry::HeadAngles& a,
                        const Eigen::Vector2d& uv, const Eigen::Vector3d& c,
                        const Eigen::Vector3d& n)
{
	const Eigen::Isometry3d T_LinC0 = head.T_LinC0(a);
	const Eigen::Vector3d o = T_LinC0.translation();
	const Eigen::Vector3d d = T_LinC0.linear() * head.camera().backProject(uv);
	const double along = n.dot(d);
	if (std::abs(along) < 1e-9) return c;  // grazing view: keep the centre
	return o + d * (n.dot(c - o) / along);
}

struct KnownPick
{
	cv::Mat patch;
	Eigen::Vector3d p_inC0;
};

/** The patch to store for the landmark at @p c_inC0 (the head fixates it) and the point it shows.
 */
KnownPick pickPatch(const vision::StereoImages& im, const geometry::BiSightHead& head,
                    const Eigen::Vector3d& c_inC0, const Eigen::Vector3d* n_inC0,
                    const vision::VisionOptions& o)
{
	const auto& cam = head.camera();
	const Eigen::Vector2d centre(cam.u0_px, cam.v0_px);
	const int side = o.known_search_box_px;
	const cv::Rect box(int(std::lround(cam.u0_px)) - side / 2,
	                   int(std::lround(cam.v0_px)) - side / 2, side, side);
	const auto corner = n_inC0 && side > 1 ? vision::bestCornerInBox(im.left, box, o.patch_size_px,
	                                                                 o.min_corner_eigenvalue)
	                                       : std::nullopt;
	const Eigen::Vector2d uv = corner ? corner->uv : centre;
	const Eigen::Vector3d p = corner ? onPlane(head, im.angles, uv, c_inC0, *n_inC0) : c_inC0;
	return {vision::extractPatch(im.left, uv, o.patch_size_px), p};
}

vision::KnownFeature acquireOne(const world::World& w, const world::Landmark& l, LiveHead& device,
                                const geometry::BiSightHead& head, const SlamSetup& s,
                                const Eigen::Vector3d& x0)
{
	const Eigen::Isometry3d T_C0inW = geometry::T_C0inW(x0, s.bisight.head_height_m);
	const Eigen::Vector3d c_inC0 = slam::pointInHead(x0, l.p_LinW, s.slam.head.constants);
	device.moveTo(head.fixate(c_inC0));
	const world::Patch* plane = device.rendersSurfaces() ? planeOf(w, l.name) : nullptr;
	const Eigen::Vector3d n_inC0 =
	    plane ? Eigen::Vector3d(T_C0inW.linear().transpose() * plane->normal) : Eigen::Vector3d();
	const KnownPick pick =
	    pickPatch(device.grab(), head, c_inC0, plane ? &n_inC0 : nullptr, s.vision);
	const vision::FixationResult r =
	    vision::fixateOnPatch(device, head, pick.patch, pick.p_inC0, s.vision);
	if (!r.locked) throw std::runtime_error("known feature '" + l.name + "': " + r.failure);
	return {l.name, T_C0inW * pick.p_inC0, pick.patch};
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
		if (wanted) out.push_back(acquireOne(w, l, device, head, s, x0));
	}
	return out;
}

}  // namespace mrolr::apps
