#pragma once
/** Devices that play a mission's recording back (docs/mission.md "Recording and replay"): each
 * request the robot side makes is checked against the next recorded call (the same device, the
 * same request, the same values to the bit) and answered with what the device answered then, its
 * pair, or the fault it raised. A request the recording does not hold there throws
 * hw::ReplayDivergence naming the call, the device and both requests: the replay never invents an
 * answer. A stop requested in the recorded run is raised at the same call. */
#include <mrolr/mission/DeviceCall.h>
#include <mrolr/mission/Mission.h>

#include <atomic>
#include <memory>
#include <string>

namespace mrolr::mission
{
class DevicePlayback
{
 public:
	/** Reads the device calls of @p rawlog_path (throws std::runtime_error naming the file and
	 * record when it cannot). */
	explicit DevicePlayback(const std::string& rawlog_path);
	~DevicePlayback();
	RobotDevices devices();
	/** The stop flag to give the mission. */
	std::atomic<bool>& stopFlag();
	/** Calls answered so far, and in the recording. */
	size_t served() const;
	size_t recorded() const;
	/** The reader's note when the recording ends inside a record (a killed run). */
	const std::string& torn() const;

	struct Impl;

 private:
	std::unique_ptr<Impl> impl_;
};

}  // namespace mrolr::mission
