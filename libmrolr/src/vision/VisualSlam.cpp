#include <mrolr/geometry/GeometryError.h>
#include <mrolr/geometry/Frames.h>
#include <mrolr/geometry/IdealHead.h>
#include <mrolr/slam/FeatureSelection.h>
#include <mrolr/slam/FeatureVisibility.h>
#include <mrolr/vision/Fixation.h>
#include <mrolr/vision/VisualSlam.h>
#include "StageTimer.h"

#include <algorithm>
#include <chrono>
#include <cmath>

namespace mrolr::vision
{
namespace
{
using detail::lap;

constexpr double kDuplicateDistance_m = 0.2;  ///< a new feature this close to a visible one is it
}  // namespace

CycleTimes& CycleTimes::operator+=(const CycleTimes& o)
{
	predict_ms += o.predict_ms, manage_ms += o.manage_ms, select_ms += o.select_ms;
	search_ms += o.search_ms, grab_ms += o.grab_ms, match_ms += o.match_ms;
	update_ms += o.update_ms;
	return *this;
}

VisualSlam::VisualSlam(slam::ActiveSlamFilter& filter, const geometry::BiSightHead& head,
                       const VisionOptions& options, const base::LabmateModel& model)
    : filter_(filter), head_(head), options_(options), model_(model)
{
}

void VisualSlam::addKnownFeature(const std::string& label, const Eigen::Vector3d& p_FinW,
                                 const cv::Mat& patch)
{
	addKnownFeature(label, p_FinW, Eigen::Matrix3d::Zero(), patch);
}

void VisualSlam::addKnownFeature(const std::string& label, const Eigen::Vector3d& p_FinW,
                                 const Eigen::Matrix3d& P_FF, const cv::Mat& patch,
                                 const std::optional<Eigen::Vector3d>& p_viewinW)
{
	filter_.addKnownFeature(label, p_FinW, P_FF, p_viewinW);
	patches_.push_back(patch.clone());
}

std::optional<size_t> VisualSlam::acquireNamed(const std::string& label,
                                               const Eigen::Vector3d& p_aim_inC0,
                                               StereoHeadDevice& device, std::string* why)
{
	try
	{
		device.moveTo(head_.fixate(p_aim_inC0));
	}
	catch (const geometry::GeometryError& e)
	{
		if (why) *why = std::string("cannot point the head there: ") + e.what();
		return std::nullopt;
	}
	const auto& cam = head_.camera();
	const int side = std::max(options_.known_search_box_px, options_.patch_size_px + 2);
	const cv::Rect box(int(cam.u0_px) - side / 2, int(cam.v0_px) - side / 2, side, side);
	const Acquisition acq = acquireFeature(device, head_, box, options_);
	CycleRecord r;
	if (!acq.ok || !addFeature(acq.fixation.p_GinC0, acq.patch, r, label))
	{
		if (why) *why = acq.ok ? "a mapped feature is already there" : acq.failure;
		return std::nullopt;
	}
	spared_.push_back(label);
	return filter_.numFeatures() - 1;
}

CycleRecord VisualSlam::step(const base::WheelControl& u, StereoHeadDevice& device,
                             const std::vector<base::WheelControl>& upcoming)
{
	CycleRecord r;
	auto t0 = std::chrono::steady_clock::now();
	if (u.dt_s > 0) filter_.predict(u);
	r.times.predict_ms = lap(t0);
	if (static_cast<int>(visibleFeatures().size()) < filter_.options().min_visible_features)
		acquireFeatures(device, r);
	r.times.manage_ms = lap(t0);
	bool measure = false;
	if (options_.selection == Selection::Saccade)
		measure = selectBySaccade(r, upcoming);
	else
	{
		selectFeature(r);
		noteSaccade(r);
		measure = r.measured;
	}
	r.times.select_ms = lap(t0);
	if (measure) measureSelected(device, r);
	deleteFailed(r);
	return r;
}

CycleRecord VisualSlam::measureFeature(size_t i, StereoHeadDevice& device)
{
	CycleRecord r;
	const auto visible = visibleFeatures();
	if (std::find(visible.begin(), visible.end(), i) == visible.end()) return r;
	r.measured = true, r.feature = i, r.label = filter_.info(i).label;
	r.vs = slam::innovationVolume(filter_.innovationCovariance(i),
	                              filter_.options().innovation_volume_sigma);
	noteSaccade(r);
	measureSelected(device, r);
	return r;
}

std::vector<size_t> VisualSlam::visibleFeatures()
{
	std::vector<size_t> out;
	const Eigen::Vector3d x_v = filter_.vehicle();
	const Eigen::Isometry3d T_WinC0 =
	    geometry::T_C0inW(x_v, head_.options().head_height_m).inverse();
	for (size_t i = 0; i < filter_.numFeatures(); ++i)
		if (slam::assessVisibility(x_v, filter_.feature(i), filter_.info(i).p_C0atInitInW,
		                           filter_.options()) == slam::Visibility::Visible &&
		    !(self_occludes && self_occludes(T_WinC0 * filter_.feature(i))))
			out.push_back(i);
	return out;
}

bool VisualSlam::isDuplicate(const Eigen::Vector3d& p_FinW)
{
	// Only visible features count: near one that the viewpoint rules of 5.2.1 hide (its patch would
	// no longer match from here), a new feature is a fresh view of that place with its own patch.
	// Counting hidden ones too left the rendered lab without measurable features for several steps
	// (seed 2 drifted by 1.1 m).
	for (size_t j : visibleFeatures())
		if ((filter_.feature(j) - p_FinW).norm() < kDuplicateDistance_m) return true;
	return false;
}

void VisualSlam::acquireFeatures(StereoHeadDevice& device, CycleRecord& r)
{
	const double pan = options_.acquire_pan_deg * M_PI / 180;
	const double tilt = options_.acquire_tilt_deg * M_PI / 180;
	const auto& cam = head_.camera();
	const int side = options_.acquire_box_px;
	const cv::Rect box(int(cam.u0_px) - side / 2, int(cam.v0_px) - side / 2, side, side);
	for (double a : {pan, 0.0, -pan})
	{
		device.moveTo({a, tilt, 0, 0});
		const Acquisition acq = acquireFeature(device, head_, box, options_);
		if (!acq.ok || !addFeature(acq.fixation.p_GinC0, acq.patch, r)) continue;
		if (static_cast<int>(visibleFeatures().size()) >= filter_.options().min_visible_features)
			return;
	}
}

bool VisualSlam::addFeature(const Eigen::Vector3d& p_GinC0, const cv::Mat& patch, CycleRecord& r,
                            const std::string& name)
{
	if (self_occludes && self_occludes(p_GinC0)) return false;  // on the robot's own arm
	const Eigen::Vector3d h = geometry::idealHeadMeasure(p_GinC0, head_.options().interocular_m);
	const auto init =
	    slam::initialiseFromMeasurement(filter_.vehicle(), h, filter_.options().head.constants);
	if (isDuplicate(init.p_FinW)) return false;
	const std::string label = name.empty() ? "F" + std::to_string(next_label_++) : name;
	filter_.initialiseFeature(label, h);
	patches_.push_back(patch.clone());
	r.added.push_back(label);
	++added_;
	tracked_ = label, head_h_ = h;  // acquisition ends fixated on it
	return true;
}

void VisualSlam::selectFeature(CycleRecord& r)
{
	for (size_t i : visibleFeatures())
	{
		const double vs = slam::innovationVolume(filter_.innovationCovariance(i),
		                                         filter_.options().innovation_volume_sigma);
		if (r.measured && vs <= r.vs) continue;
		r.measured = true, r.feature = i, r.vs = vs;
	}
	if (r.measured) r.label = filter_.info(r.feature).label;
}

void VisualSlam::measureSelected(StereoHeadDevice& device, CycleRecord& r)
{
	matchSelected(device, r);
	auto t0 = std::chrono::steady_clock::now();
	applyMeasurement(r);
	r.times.update_ms = lap(t0);
}

void VisualSlam::matchSelected(StereoHeadDevice& device, CycleRecord& r)
{
	auto t0 = std::chrono::steady_clock::now();
	const Eigen::Vector3d h_pred = filter_.predictedMeasurement(r.feature);
	const Eigen::Matrix3d S = filter_.innovationCovariance(r.feature);
	FeatureMeasurement& m = r.measurement;
	bool ok = false;
	try
	{
		const Eigen::Vector3d p = geometry::idealHeadInverse(h_pred, head_.options().interocular_m);
		device.moveTo(head_.fixate(p));
		ok = predictRegions(head_, device.angles(), h_pred, S, options_, m);
	}
	catch (const geometry::GeometryError&)
	{
	}
	catch (const std::invalid_argument&)
	{
	}
	r.times.search_ms = lap(t0);
	if (ok)
	{
		const StereoImages images = device.grab();
		r.times.grab_ms = lap(t0);
		matchInRegions(images, head_, patches_[r.feature], options_, NssdMethod::OpenCv, m);
		r.times.match_ms = lap(t0);
	}
}

void VisualSlam::applyMeasurement(CycleRecord& r)
{
	if (r.measurement.found)
	{
		const slam::UpdateReport rep =
		    filter_.update({slam::Observation{r.feature, r.measurement.h}});
		r.accepted = !rep.accepted.empty();
		if (!rep.nis.empty()) r.nis = rep.nis.front();
		if (!rep.rejected_nis.empty()) r.nis = rep.rejected_nis.front();
	}
	filter_.recordAttempt(r.feature, r.accepted);
}

void VisualSlam::deleteFailed(CycleRecord& r)
{
	for (size_t i = filter_.numFeatures(); i-- > 0;)
	{
		const auto& label = filter_.info(i).label;
		const bool spared = std::find(spared_.begin(), spared_.end(), label) != spared_.end();
		if (filter_.info(i).known || spared || !filter_.shouldDelete(i)) continue;
		r.deleted.push_back(filter_.info(i).label);
		filter_.deleteFeature(i);
		patches_.erase(patches_.begin() + static_cast<long>(i));
		++deleted_;
	}
}

}  // namespace mrolr::vision
