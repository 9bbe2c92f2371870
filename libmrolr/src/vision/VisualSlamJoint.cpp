// One step's measurements made first and tested jointly before any is used (joint compatibility,
// Neira & Tardós 2001), the nearest known feature measured first (thesis 7.2(a)).
#include <mrolr/slam/FeatureSelection.h>
#include <mrolr/slam/JointCompatibility.h>
#include <mrolr/slam/HeadMeasurement.h>
#include <mrolr/vision/VisualSlam.h>
#include "StageTimer.h"

#include <algorithm>
#include <chrono>

namespace mrolr::vision
{
using detail::lap;

std::vector<size_t> VisualSlam::chooseForStep(int count)
{
	const auto visible = visibleFeatures();
	const Eigen::Vector3d c0 = slam::headCentreInW(filter_.vehicle(), filter_.options().head.constants);
	std::vector<size_t> out;
	std::optional<size_t> nearest;
	for (size_t i : visible)
		if (filter_.info(i).known &&
		    (!nearest || (filter_.feature(i) - c0).norm() < (filter_.feature(*nearest) - c0).norm()))
			nearest = i;
	if (nearest) out.push_back(*nearest);
	std::vector<std::pair<double, size_t>> by_vs;
	for (size_t i : visible)
		if (!nearest || i != *nearest)
			by_vs.emplace_back(slam::innovationVolume(filter_.innovationCovariance(i),
			                                          filter_.options().innovation_volume_sigma),
			                   i);
	std::sort(by_vs.rbegin(), by_vs.rend());
	for (const auto& [vs, i] : by_vs)
		if (static_cast<int>(out.size()) < count) out.push_back(i);
	return out;
}

void VisualSlam::applyJointly(std::vector<CycleRecord>& records)
{
	std::vector<slam::Observation> candidates;
	std::vector<size_t> which;
	for (size_t k = 0; k < records.size(); ++k)
		if (records[k].measurement.found)
			candidates.push_back({records[k].feature, records[k].measurement.h}), which.push_back(k);
	std::vector<slam::Observation> compatible;
	if (!candidates.empty())
	{
		const auto jc = slam::jointlyCompatible(filter_, candidates,
		                                        filter_.options().gate_probability);
		for (size_t a = 0; a < candidates.size(); ++a)
		{
			const bool in = std::count(jc.accepted.begin(), jc.accepted.end(), a) > 0;
			records[which[a]].jointly_rejected = !in;
			if (in) compatible.push_back(candidates[a]);
		}
	}
	const slam::UpdateReport rep =
	    compatible.empty() ? slam::UpdateReport{} : filter_.update(compatible);
	for (auto& r : records)
	{
		for (size_t a = 0; a < rep.accepted.size(); ++a)
			if (rep.accepted[a] == r.feature) r.accepted = true, r.nis = rep.nis[a];
		for (size_t a = 0; a < rep.rejected.size(); ++a)
			if (rep.rejected[a] == r.feature) r.nis = rep.rejected_nis[a];
		filter_.recordAttempt(r.feature, r.accepted);
	}
}

std::vector<CycleRecord> VisualSlam::stepJoint(const base::WheelControl& u,
                                               StereoHeadDevice& device, int count)
{
	CycleRecord first;
	auto t0 = std::chrono::steady_clock::now();
	if (u.dt_s > 0) filter_.predict(u);
	first.times.predict_ms = lap(t0);
	if (static_cast<int>(visibleFeatures().size()) < filter_.options().min_visible_features)
		acquireFeatures(device, first);
	first.times.manage_ms = lap(t0);
	std::vector<CycleRecord> out;
	for (size_t i : chooseForStep(count))
	{
		CycleRecord r;
		r.measured = true, r.feature = i, r.label = filter_.info(i).label;
		r.vs = slam::innovationVolume(filter_.innovationCovariance(i),
		                              filter_.options().innovation_volume_sigma);
		noteSaccade(r);
		matchSelected(device, r);
		out.push_back(std::move(r));
	}
	if (out.empty()) out.push_back(std::move(first));
	else
	{
		auto t1 = std::chrono::steady_clock::now();
		applyJointly(out);
		out.front().times.update_ms += lap(t1);
		out.front().added = first.added;
		out.front().times += first.times;
	}
	deleteFailed(out.back());
	return out;
}

}  // namespace mrolr::vision
