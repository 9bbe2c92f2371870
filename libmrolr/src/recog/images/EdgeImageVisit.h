#pragma once
// EdgeImage's walk over the samples of a pose (forEachInView), shared by the scores
// (ImageVerifier.cpp) and the edge-line terms of the refinement (ImageEdgeLines.cpp).
#include <mrolr/recog/images/ImageVerifier.h>
#include <mrolr/recog/images/ProjectedRun.h>

#include <algorithm>

namespace mrolr::recog
{
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
	// sample j of run r (projectRun: its point and pixels, computed for the run at once)
	const auto visit = [&](const EdgeSample& s, const SelfOcclusion::PointSight* sight,
	                       const ProjectedRun& r, size_t j)
	{
		if (!r.in_view[j] && !outside) return;
		// a limb is on the outline by construction: only the model's parts off its bodies (a
		// handle) can hide it (SelfOcclusion::hiddenLimb)
		const bool limb = sight == nullptr;
		const bool hidden =
		    occ && (limb                     ? occ->hiddenLimb(view, s.p_O)
		            : revolution_visibility_ ? occ->hiddenOnBodies(view, *sight, s.p_O)
		                                     : occ->hidden(view, *sight, s.p_O));
		if (!r.in_view[j])
		{
			*outside += hidden ? 0 : 1;
			return;
		}
		if (hidden && !kHiddenToo) return;
		const cv::Point2d px(r.u[j], r.v[j]);
		if (inside.contains(px))
			fn(px, cv::Point2d(r.tu[j], r.tv[j]), hidden, limb,
			   Eigen::Vector3d(r.x[j], r.y[j], r.z[j]));
		else if (outside && !hidden)
			++*outside;
	};
	static const SelfOcclusion::PointSight kNoSight;
	ProjectedRun run;
	// each run is projected at once; the stop is asked after each sample, as before
	const auto walk = [&](const std::vector<EdgeSample>& samples, bool with_sights)
	{
		for (size_t first = 0; first < samples.size(); first += ProjectedRun::kMax)
		{
			const size_t n = std::min(ProjectedRun::kMax, samples.size() - first);
			projectRun(T_OinC, K_, D_, samples.data() + first, n, run);
			for (size_t j = 0; j < n; ++j)
			{
				const size_t k = first + j;
				visit(samples[k], !with_sights ? nullptr : occ ? &ss.sights[k] : &kNoSight, run, j);
				if (stop()) return false;
			}
		}
		return true;
	};
	if (walk(ss.samples_O, true)) walk(limbs, false);
}

}  // namespace mrolr::recog
