#include <mrolr/vision/PairAcquisition.h>

#include <sstream>

namespace mrolr::vision
{
namespace
{
std::string notFoundAlongEpipolar(const PatchMatch& m, double threshold)
{
	std::ostringstream s;
	s << "patch not found in the right image along the epipolar line (best NSSD " << m.score
	  << " over " << m.candidates << " candidates, threshold " << threshold << ")";
	return s.str();
}
}  // namespace

PairAcquisition acquireInPair(const StereoImages& im, const geometry::BiSightHead& head,
                              const cv::Rect& box, const VisionOptions& o)
{
	PairAcquisition a;
	const auto corner = bestCornerInBox(im.left, box, o.patch_size_px, o.min_corner_eigenvalue);
	if (!corner)
	{
		a.failure = "no Shi-Tomasi feature above min_corner_eigenvalue in the search box";
		return a;
	}
	a.corner = *corner;
	a.patch = extractPatch(im.left, corner->uv, o.patch_size_px);
	try
	{
		const EpipolarBand band = epipolarBand(head, im.angles, corner->uv, o.epipolar_min_depth_m,
		                                       o.epipolar_max_depth_m, o.epipolar_band_px);
		a.right_match = searchEpipolar(im.right, a.patch, band, o.nssd_threshold);
		if (!a.right_match.found)
		{
			a.failure = notFoundAlongEpipolar(a.right_match, o.nssd_threshold);
			return a;
		}
		a.pixels = {corner->uv.x(), corner->uv.y(), a.right_match.uv.x(), a.right_match.uv.y()};
		a.p_GinC0 = head.triangulatePoint(a.pixels, im.angles);
	}
	catch (const geometry::GeometryError& e)
	{
		a.failure = std::string("cannot triangulate the new feature: ") + e.what();
		return a;
	}
	a.ok = true;
	return a;
}

}  // namespace mrolr::vision
