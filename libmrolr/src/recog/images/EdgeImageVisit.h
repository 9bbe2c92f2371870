#pragma once
// EdgeImage's walk over the samples of a pose (forEachInView), shared by the scores
// (ImageVerifier.cpp) and the edge-line terms of the refinement (ImageEdgeLines.cpp).
#include <mrolr/recog/images/ImageVerifier.h>

#include <cmath>

namespace mrolr::recog
{
namespace detail
{
inline bool inView(const Eigen::Vector3d& p_C)
{
	// points far outside the view are dropped: the distortion polynomial folds them back in
	return p_C.z() > 1 && std::abs(p_C.x()) < p_C.z() && std::abs(p_C.y()) < p_C.z();
}

/** cv::projectPoints of one point already in the camera frame (no rotation, no translation) with
 * the 5 coefficients k1 k2 p1 p2 k3, written out in OpenCV's order of operations (it gives the
 * same pixels, and takes a fifth of the time of the call per point). */
inline cv::Point2d projected(const cv::Matx33d& K, const cv::Vec<double, 5>& D,
                             const Eigen::Vector3d& p)
{
	const double iz = p.z() != 0 ? 1. / p.z() : 1;
	const double x = p.x() * iz, y = p.y() * iz;
	const double r2 = x * x + y * y, r4 = r2 * r2, r6 = r4 * r2;
	const double a1 = 2 * x * y, a2 = r2 + 2 * x * x, a3 = r2 + 2 * y * y;
	const double cdist = 1 + D[0] * r2 + D[1] * r4 + D[4] * r6;
	const double xd = x * cdist + D[2] * a1 + D[3] * a2;
	const double yd = y * cdist + D[2] * a3 + D[3] * a1;
	return {xd * K(0, 0) + K(0, 2), yd * K(1, 1) + K(1, 2)};
}
}  // namespace detail

template <bool kHiddenToo, class Fn, class Stop>
void EdgeImage::forEachInView(const SightedSamples& ss, const Eigen::Isometry3d& T_OinL,
                              const std::vector<EdgeSample>& limbs, Fn fn, Stop stop,
                              int* outside) const
{
	const SelfOcclusion* occ = ss.occ;
	const Eigen::Isometry3d T_OinC = T_LinCcv_ * T_OinL;
	const Eigen::Vector3d c_O = T_OinL.inverse() * centre_L();
	const SelfOcclusion::View view = occ ? occ->viewFrom(c_O) : SelfOcclusion::View();
	const cv::Rect2d inside(0, 0, edges_.cols - 1, edges_.rows - 1);
	const auto visit = [&](const EdgeSample& s, const SelfOcclusion::PointSight* sight)
	{
		const Eigen::Vector3d p = T_OinC * s.p_O, q = p + T_OinC.linear() * s.t_O;
		const bool in_view = detail::inView(p) && detail::inView(q);
		if (!in_view && !outside) return;
		// a limb is on the outline by construction: only the model's parts off its bodies (a
		// handle) can hide it (SelfOcclusion::hiddenLimb)
		const bool limb = sight == nullptr;
		const bool hidden =
		    occ && (limb                     ? occ->hiddenLimb(view, s.p_O)
		            : revolution_visibility_ ? occ->hiddenOnBodies(view, *sight, s.p_O)
		                                     : occ->hidden(view, *sight, s.p_O));
		if (!in_view)
		{
			*outside += hidden ? 0 : 1;
			return;
		}
		if (hidden && !kHiddenToo) return;
		const cv::Point2d px = detail::projected(K_, D_, p);
		if (inside.contains(px))
			fn(px, detail::projected(K_, D_, q) - px, hidden, limb, p);
		else if (outside && !hidden)
			++*outside;
	};
	static const SelfOcclusion::PointSight kNoSight;
	for (size_t k = 0; k < ss.samples_O.size(); ++k)
	{
		visit(ss.samples_O[k], occ ? &ss.sights[k] : &kNoSight);
		if (stop()) return;
	}
	for (const auto& s : limbs)
	{
		visit(s, nullptr);
		if (stop()) return;
	}
}

}  // namespace mrolr::recog
