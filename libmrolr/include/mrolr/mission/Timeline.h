#pragma once
/** The mission's clocks: simulated physical time (what the robot would take), the robot's own
 * compute time (filter, recognition, planning, IK) and the simulator's time, kept apart as the
 * issue asks; and a timeline of events with their simulated time. */
#include <chrono>
#include <functional>
#include <map>
#include <string>
#include <vector>

namespace mrolr::mission
{
struct TimelineEvent
{
	double time_s = 0;  ///< simulated time
	std::string stage, text;
};

class Timeline
{
 public:
	/** Adds simulated physical time (motion, head moves, arm moves), seconds. */
	void advance(double seconds) { simulated_s_ += seconds; }
	double simulatedSeconds() const { return simulated_s_; }
	/** Adds robot compute time (wall seconds) to the total and to the current stage. */
	void addCompute(double seconds);
	double computeSeconds() const { return compute_s_; }
	/** Adds the simulator's rendering time (wall seconds), kept apart from the robot's compute. */
	void addRender(double seconds) { render_s_ += seconds; }
	double renderSeconds() const { return render_s_; }
	/** Starts a stage: the previous one's simulated duration is closed. */
	void beginStage(const std::string& name);
	/** Closes the current stage. */
	void endStage();
	const std::string& stage() const { return stage_; }
	/** Stage name → simulated seconds (a stage run twice adds up). */
	const std::map<std::string, double>& stageSeconds() const { return stage_s_; }
	const std::map<std::string, double>& stageComputeSeconds() const { return stage_compute_s_; }
	void note(const std::string& text);
	/** Called with each note as it is made (a recording's decisions). */
	std::function<void(const TimelineEvent&)> on_note;
	const std::vector<TimelineEvent>& events() const { return events_; }

 private:
	double simulated_s_ = 0, compute_s_ = 0, render_s_ = 0, stage_start_s_ = 0;
	std::string stage_;
	std::map<std::string, double> stage_s_, stage_compute_s_;
	std::vector<TimelineEvent> events_;
};

/** Measures the wall time of a scope and adds it to a timeline's compute time. */
class ComputeTimer
{
 public:
	explicit ComputeTimer(Timeline& t) : t_(t), start_(std::chrono::steady_clock::now()) {}
	~ComputeTimer()
	{
		t_.addCompute(
		    std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count());
	}

 private:
	Timeline& t_;
	std::chrono::steady_clock::time_point start_;
};

}  // namespace mrolr::mission
