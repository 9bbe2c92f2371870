// Simulated, compute and per-stage times of a mission.
#include <mrolr/mission/Timeline.h>

namespace mrolr::mission
{
void Timeline::addCompute(double seconds)
{
	compute_s_ += seconds;
	if (!stage_.empty()) stage_compute_s_[stage_] += seconds;
}

void Timeline::beginStage(const std::string& name)
{
	endStage();
	stage_ = name;
	stage_start_s_ = simulated_s_;
	note("begin");
}

void Timeline::endStage()
{
	if (stage_.empty()) return;
	stage_s_[stage_] += simulated_s_ - stage_start_s_;
	stage_.clear();
}

void Timeline::note(const std::string& text)
{
	events_.push_back({simulated_s_, stage_, text});
	if (on_note) on_note(events_.back());
}

}  // namespace mrolr::mission
