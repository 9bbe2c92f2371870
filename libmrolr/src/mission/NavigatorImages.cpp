// Navigation measurements from the head's stereo pairs (measurement_source = images): the vision
// area's cycle (thesis 5.5–5.7) on the mission's filter; docs/mission.md "Measurements from
// images".
#include <mrolr/mission/Navigator.h>

#include <chrono>

namespace mrolr::mission
{
void Navigator::measureInImages(const base::WheelControl& u)
{
	for (int k = 0; k < std::max(1, o_.navigation.measurements_per_step); ++k)
	{
		const double grab0 = grab_seconds_();
		const auto t0 = std::chrono::steady_clock::now();
		// The first cycle predicts with the step's control; the others measure only (dt = 0).
		const auto rec = vslam_->step(k == 0 ? u : base::WheelControl{}, *images_head_);
		const double wall =
		    std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
		const double grab = grab_seconds_() - grab0;
		timeline_.addRender(grab);
		timeline_.addCompute(std::max(0.0, wall - grab));
		if (!rec.measured) continue;
		timeline_.advance(o_.navigation.measurement_time_s);
		++image_cycles;
		image_matched += rec.measurement.found ? 1 : 0;
		(rec.accepted ? measurements : rejected) += 1;
	}
}

}  // namespace mrolr::mission
