#include <mrolr/vision/Fixation.h>
#include <mrolr/vision/PairAcquisition.h>

#include <sstream>

namespace mrolr::vision
{
using geometry::BiSightHead;
using geometry::HeadAngles;
using geometry::StereoPixels;

bool isLockedOn(const StereoPixels& px, const geometry::PinholeCamera& camera, double radius_px)
{
	const Eigen::Vector2d pp(camera.u0_px, camera.v0_px);
	return (Eigen::Vector2d(px.uL, px.vL) - pp).norm() <= radius_px &&
	       (Eigen::Vector2d(px.uR, px.vR) - pp).norm() <= radius_px;
}

namespace
{
std::string notFound(const char* side, const PatchMatch& m, double threshold)
{
	std::ostringstream s;
	s << "patch not found in the " << side << " image (best NSSD " << m.score << " over "
	  << m.candidates << " candidates, threshold " << threshold << ")";
	return s.str();
}

/** One attempt: saccade to @p p, grab, find the patch near the principal point in both images and
 * triangulate. Returns false (with r.failure set) when the patch was lost. */
bool fixationStep(StereoHeadDevice& device, const BiSightHead& head, const cv::Mat& patch,
                  const Eigen::Vector3d& p, const VisionOptions& o, FixationResult& r)
{
	r.angles = head.fixate(p);
	device.moveTo(r.angles);
	const StereoImages im = device.grab();
	const StereoPixels pred = head.project(p, r.angles);
	const double thr = o.nssd_threshold, rad = o.fixation_search_radius_px;
	const PatchMatch mL = searchSquare(im.left, patch, {pred.uL, pred.vL}, rad, thr);
	const PatchMatch mR = searchSquare(im.right, patch, {pred.uR, pred.vR}, rad, thr);
	r.score_left = mL.score, r.score_right = mR.score;
	if (!mL.found || !mR.found)
	{
		r.failure = notFound(mL.found ? "right" : "left", mL.found ? mR : mL, thr);
		return false;
	}
	r.pixels = {mL.uv.x(), mL.uv.y(), mR.uv.x(), mR.uv.y()};
	const geometry::Triangulation t = head.triangulate(r.pixels, r.angles, o.pixel_sigma_px);
	r.p_GinC0 = t.p_GinC0, r.cov_C0 = t.cov;
	return true;
}
}  // namespace

FixationResult fixateOnPatch(StereoHeadDevice& device, const BiSightHead& head,
                             const cv::Mat& patch, const Eigen::Vector3d& p_guess_inC0,
                             const VisionOptions& options)
{
	FixationResult r;
	Eigen::Vector3d p = p_guess_inC0;
	try
	{
		while (r.attempts < options.fixation_max_attempts)
		{
			++r.attempts;
			if (!fixationStep(device, head, patch, p, options, r)) return r;
			if (isLockedOn(r.pixels, head.camera(), options.lockon_radius_px))
			{
				r.locked = true;
				return r;
			}
			p = r.p_GinC0;
		}
		r.failure = "no lock-on after " + std::to_string(r.attempts) + " attempts";
	}
	catch (const geometry::GeometryError& e)
	{
		r.failure = std::string("cannot fixate: ") + e.what();
	}
	return r;
}

Acquisition acquireFeature(StereoHeadDevice& device, const BiSightHead& head, const cv::Rect& box,
                           const VisionOptions& o)
{
	Acquisition a;
	const PairAcquisition pair = acquireInPair(device.grab(), head, box, o);
	a.corner = pair.corner, a.patch = pair.patch, a.right_match = pair.right_match;
	if (!pair.ok)
	{
		a.failure = pair.failure;
		return a;
	}
	a.fixation = fixateOnPatch(device, head, a.patch, pair.p_GinC0, o);
	a.ok = a.fixation.locked;
	if (!a.ok) a.failure = "fixation failed: " + a.fixation.failure;
	return a;
}

}  // namespace mrolr::vision
