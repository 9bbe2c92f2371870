// Navigation measurements from the head's stereo pairs (landmark_sensor = images): the vision
// area's cycle (thesis 5.5–5.7) on the mission's filter, one step's matches tested jointly;
// docs/mission.md "Measurements from images".
#include <mrolr/geometry/Frames.h>
#include <mrolr/mission/Navigator.h>

#include <chrono>

namespace mrolr::mission
{
void Navigator::measureInImages(const base::WheelControl& u)
{
	const double grab0 = grab_seconds_();
	const auto t0 = std::chrono::steady_clock::now();
	const auto records =
	    vslam_->stepJoint(u, *images_head_, std::max(1, o_.navigation.measurements_per_step));
	const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
	const double grab = grab_seconds_() - grab0;
	timeline_.addRender(grab);
	timeline_.addCompute(std::max(0.0, wall - grab));
	for (const auto& rec : records)
	{
		for (const auto& f : rec.deleted) timeline_.note("feature " + f + " deleted (rule 5.7)");
		if (on_measurement) on_measurement(rec);
		if (!rec.measured) continue;
		timeline_.advance(o_.navigation.measurement_time_s);
		++image_cycles;
		image_matched += rec.measurement.found ? 1 : 0;
		jointly_rejected += rec.jointly_rejected ? 1 : 0;
		(rec.accepted ? measurements : rejected) += 1;
		if (rec.nis) noteNis(rec.label, *rec.nis, rec.accepted);
		noteAttempt(rec.accepted);
	}
	checkLost();
}

bool Navigator::acquireNamed(const std::string& label, const Eigen::Vector3d& p_aim_inW,
                             std::string& why)
{
	if (!vslam_)
	{
		why = "not navigating from images";
		return false;
	}
	ComputeTimer t(timeline_);
	const Eigen::Isometry3d T_C0inW = geometry::T_C0inW(filter_.vehicle(), o_.bisight.head_height_m);
	const bool ok = vslam_->acquireNamed(label, T_C0inW.inverse() * p_aim_inW, *images_head_, &why)
	                    .has_value();
	timeline_.advance(o_.navigation.measurement_time_s);
	return ok;
}

std::vector<SavedFeature> Navigator::savedFeatures()
{
	std::vector<SavedFeature> out;
	if (!vslam_) return out;
	const auto map = this->map();
	for (size_t i = 0; i < map.size(); ++i)
	{
		const auto& info = filter_.info(i);
		out.push_back({map[i], vslam_->patches()[i], info.p_C0atInitInW, info.successes,
		               info.failures});
	}
	return out;
}

}  // namespace mrolr::mission
