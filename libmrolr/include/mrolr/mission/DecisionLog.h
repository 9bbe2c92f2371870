#pragma once
/** Where the mission reports what it decided, as it decides it, for a recording to show
 * (DeviceRecorder writes them into mission.rawlog for RawLogViewer). Inspection only: a replay
 * recomputes every decision from the recorded device answers and never reads these. */
#include <mrolr/mission/Navigator.h>
#include <mrolr/mission/ObjectSearch.h>
#include <mrolr/mission/Retrieval.h>
#include <mrolr/mission/Timeline.h>
#include <mrolr/model/WireFrame.h>
#include <mrolr/vision/VisualSlam.h>

namespace mrolr::mission
{
class DecisionLog
{
 public:
	virtual ~DecisionLog() = default;
	/** The estimate and its covariance after a step (z, x, φ in W; P_vv). */
	virtual void estimate(const PathSample& s) = 0;
	/** A navigation measurement from images: the selected feature, its search ellipses, the
	 * match, accepted or refused and its NIS (thesis 5.5–5.7). */
	virtual void measurement(const vision::CycleRecord& c) = 0;
	/** The object recognised (@p r.T_OinL_mm, T_OinC0_mm) at the estimate @p xv_estimate, with
	 * the model @p target that was recognised. */
	virtual void recognised(const SearchResult& r, const Eigen::Vector3d& xv_estimate,
	                        const model::WireFrame& target) = 0;
	/** The grasp the arm was sent to (T_GinA, mm; the joint solution). */
	virtual void graspPlanned(const RetrievalResult& r) = 0;
	/** A timeline note (stage changes, refusals, what was found where). */
	virtual void note(const TimelineEvent& e) = 0;
};

}  // namespace mrolr::mission
