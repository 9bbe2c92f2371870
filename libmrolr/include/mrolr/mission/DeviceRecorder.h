#pragma once
/** The recording of a mission as it happens (docs/mission.md "Recording and replay"): devices
 * that pass every call on to the real ones and write it, with the device's answer, into
 * mission.rawlog (DeviceCall.h; a writer thread encodes the images and writes the records in
 * order while the robot goes on, io/ObservationQueue.h), so that a replay (DevicePlayback.h) can answer
 * the same requests with the same answers. Beside the calls it writes what a reader of the
 * rawlog wants to see: each odometry reading as a CObservationOdometry (`ODOMETRY`), a pressed
 * bumper (`BUMPER`), and the robot's decisions (DecisionLog). */
#include <mrolr/mission/DecisionLog.h>
#include <mrolr/io/ObservationQueue.h>
#include <mrolr/mission/DeviceCall.h>
#include <mrolr/mission/Mission.h>

#include <atomic>
#include <functional>
#include <memory>
#include <string>

namespace mrolr::mission
{
class DeviceRecorder : public DecisionLog
{
 public:
	/** Creates the rawlog at @p rawlog_path (throws std::runtime_error naming it) and records
	 * the calls made to @p devices; @p head is the robot's head calibration (for the pairs'
	 * camera poses). */
	DeviceRecorder(const std::string& rawlog_path, RobotDevices devices,
	               const geometry::BiSightHead& head);
	~DeviceRecorder() override;
	/** The devices to give the mission. */
	RobotDevices devices();
	/** The stop flag to give the mission: raised at the first device call after @p signal is
	 * (SIGINT, SIGTERM), and the recording marks that call, so a replay raises it there too. */
	std::atomic<bool>& stopFlag(std::atomic<bool>* signal);
	/** Called after each base step: the world side's truth, recorded beside (may be null). */
	std::function<mrpt::obs::CObservation::Ptr()> world_truth;
	/** Records @p obs after what was recorded so far (nothing for a null one). */
	void write(mrpt::obs::CObservation::Ptr obs);
	/** Waits until everything recorded so far is in the file (throws std::runtime_error naming
	 * the file when a write failed; a failed write also stops the next device call). */
	void flush();
	/** The recording's figures (after flush()): records, images, bytes, the writer's time. */
	io::ObservationQueue::Stats stats();
	size_t calls() const;

	void estimate(const PathSample& s) override;
	void measurement(const vision::CycleRecord& c) override;
	void recognised(const SearchResult& r, const Eigen::Vector3d& xv_estimate,
	                const model::WireFrame& target) override;
	void graspPlanned(const RetrievalResult& r) override;
	void note(const TimelineEvent& e) override;

	struct Impl;

 private:
	std::unique_ptr<Impl> impl_;
};

}  // namespace mrolr::mission
