// Feature selection by the saccade decision of thesis 5.7 steps 1-4 in the live cycle: a saccade
// to another feature costs the measurements of the time the head needs to get there.
#include <mrolr/geometry/GeometryError.h>
#include <mrolr/slam/FeatureSelection.h>
#include <mrolr/slam/FeatureVisibility.h>
#include <mrolr/slam/HeadMeasurement.h>
#include <mrolr/vision/VisualSlam.h>

#include <algorithm>

namespace mrolr::vision
{
namespace
{
std::optional<size_t> indexOf(const slam::ActiveSlamFilter& filter, size_t n,
                              const std::string& label)
{
	for (size_t i = 0; i < n; ++i)
		if (filter.info(i).label == label) return i;
	return std::nullopt;
}
}  // namespace

void VisualSlam::noteSaccade(CycleRecord& r)
{
	if (!r.measured) return;
	const Eigen::Vector3d h = filter_.predictedMeasurement(r.feature);
	r.saccade = r.label != tracked_;
	r.measurements_lost =
	    r.saccade ? slam::measurementsLostBySaccade(head_h_, h, filter_.options()) : 0;
	tracked_ = r.label, head_h_ = h;
}

bool VisualSlam::selectBySaccade(CycleRecord& r, const std::vector<base::WheelControl>& upcoming)
{
	auto choose = [&](size_t i)
	{
		r.measured = true, r.feature = i, r.label = filter_.info(i).label;
		r.vs = slam::innovationVolume(filter_.innovationCovariance(i),
		                              filter_.options().innovation_volume_sigma);
	};
	if (waiting_ > 0 && --waiting_ > 0)
	{
		r.waiting = true, r.label = pending_;
		return false;
	}
	const auto visible = visibleFeatures();
	if (!pending_.empty())  // the head has arrived at the feature chosen earlier
	{
		const auto i = indexOf(filter_, filter_.numFeatures(), pending_);
		pending_.clear();
		if (i && std::count(visible.begin(), visible.end(), *i))
		{
			choose(*i);
			return true;
		}
	}
	slam::SaccadeQuery q;
	q.x = filter_.stateVector(), q.P = filter_.covariance(), q.visible = visible;
	q.current = indexOf(filter_, filter_.numFeatures(), tracked_);
	q.head_angles = head_h_, q.upcoming = upcoming;
	const slam::SaccadeDecision d = slam::decideSaccade(q, filter_.options(), model_);
	if (!d.feature) return false;
	choose(*d.feature);
	noteSaccade(r);
	if (r.measurements_lost == 0) return true;
	pending_ = r.label, waiting_ = r.measurements_lost;
	r.measured = false, r.waiting = true;
	return false;
}

void VisualSlam::holdGaze(const Eigen::Vector3d& xv_after, StereoHeadDevice& device)
{
	const auto i = indexOf(filter_, filter_.numFeatures(), tracked_);
	if (!i) return;
	const Eigen::Vector3d p = filter_.feature(*i);
	if (slam::headCanFixate(xv_after, p, filter_.options().head) != slam::Visibility::Visible)
		return;
	try
	{
		device.moveTo(head_.fixate(slam::pointInHead(xv_after, p, filter_.options().head.constants)));
	}
	catch (const geometry::GeometryError&)
	{
	}
}

}  // namespace mrolr::vision
