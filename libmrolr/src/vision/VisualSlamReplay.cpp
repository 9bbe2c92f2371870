// The cycle of VisualSlam on recorded frames (rawlog replay): the head cannot be steered, so
// features are acquired and measured wherever the recorded gaze looked.
#include <mrolr/geometry/IdealHead.h>
#include <mrolr/slam/FeatureSelection.h>
#include <mrolr/vision/PairAcquisition.h>
#include <mrolr/vision/VisualSlam.h>
#include "StageTimer.h"

#include <algorithm>
#include <chrono>
#include <stdexcept>

namespace mrolr::vision
{
using detail::lap;

std::vector<size_t> VisualSlam::featuresInView(const geometry::HeadAngles& angles,
                                               const cv::Size& size)
{
	const double margin = options_.patch_size_px / 2;
	auto inside = [&](double u, double v)
	{
		return u >= margin && v >= margin && u <= size.width - 1 - margin &&
		       v <= size.height - 1 - margin;
	};
	std::vector<size_t> out;
	for (size_t i : visibleFeatures())
	{
		try
		{
			const Eigen::Vector3d p = geometry::idealHeadInverse(filter_.predictedMeasurement(i),
			                                                     head_.options().interocular_m);
			const geometry::StereoPixels px = head_.project(p, angles);
			if (inside(px.uL, px.vL) && inside(px.uR, px.vR)) out.push_back(i);
		}
		catch (const geometry::GeometryError&)  // behind a camera
		{
		}
		catch (const std::invalid_argument&)  // vergence outside (0, π/2)
		{
		}
	}
	return out;
}

void VisualSlam::acquireInFrame(const StereoImages& images, CycleRecord& r)
{
	const auto& cam = head_.camera();
	const int side = options_.acquire_box_px;
	const cv::Rect image(0, 0, images.left.cols, images.left.rows);
	size_t in_view = featuresInView(images.angles, images.left.size()).size();
	for (int k : {0, -1, 1})
	{
		if (static_cast<int>(in_view) >= filter_.options().min_visible_features) return;
		const cv::Rect box =
		    cv::Rect(int(cam.u0_px) - side / 2 + k * side, int(cam.v0_px) - side / 2, side, side) &
		    image;
		if (box.empty()) continue;
		const PairAcquisition acq = acquireInPair(images, head_, box, options_);
		if (acq.ok && addFeature(acq.p_GinC0, acq.patch, r)) ++in_view;
	}
}

CycleRecord VisualSlam::measureInFrame(size_t i, const StereoImages& images)
{
	CycleRecord r;
	auto t0 = std::chrono::steady_clock::now();
	r.measured = true, r.feature = i, r.label = filter_.info(i).label;
	const Eigen::Matrix3d S = filter_.innovationCovariance(i);
	r.vs = slam::innovationVolume(S, filter_.options().innovation_volume_sigma);
	const bool ok = predictRegions(head_, images.angles, filter_.predictedMeasurement(i), S,
	                               options_, r.measurement);
	r.times.search_ms = lap(t0);
	if (ok) matchInRegions(images, head_, patches_[i], options_, NssdMethod::OpenCv, r.measurement);
	r.times.match_ms = lap(t0);
	applyMeasurement(r);
	r.times.update_ms = lap(t0);
	return r;
}

std::vector<CycleRecord> VisualSlam::replayFrame(const base::WheelControl& u,
                                                 const StereoImages* images)
{
	CycleRecord first;
	auto t0 = std::chrono::steady_clock::now();
	if (u.dt_s > 0) filter_.predict(u);
	first.times.predict_ms = lap(t0);
	if (!images) return {first};
	const size_t mapped_before = filter_.numFeatures();
	acquireInFrame(*images, first);
	first.times.manage_ms = lap(t0);
	// New features were initialised from this very pair: measuring them again adds nothing.
	std::vector<std::pair<double, size_t>> order;
	for (size_t i : featuresInView(images->angles, images->left.size()))
		if (i < mapped_before)
			order.emplace_back(slam::innovationVolume(filter_.innovationCovariance(i), 1.0), i);
	std::sort(order.rbegin(), order.rend());
	first.times.select_ms = lap(t0);
	std::vector<CycleRecord> out;
	for (const auto& [vs, i] : order)
	{
		CycleRecord r = measureInFrame(i, *images);
		if (out.empty()) r.added = first.added, r.times += first.times;
		out.push_back(std::move(r));
	}
	if (out.empty()) out.push_back(std::move(first));
	deleteFailed(out.back());
	return out;
}

}  // namespace mrolr::vision
