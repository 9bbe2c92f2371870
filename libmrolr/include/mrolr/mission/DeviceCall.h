#pragma once
/** The robot's device calls as rawlog observations (docs/mission.md "Recording and replay"). Every
 * request the robot side makes of its devices (hw::BaseDevice, HeadDevice, ArmDevice) and the
 * device's answer become one CObservationRawDAQ whose sensor label names the call (`BASE_STEP`,
 * `BASE_ODOMETRY`, `HEAD_MOVE`, `HEAD_ANGLES`, `HEAD_GRAB`, `ARM_MOVE`, `ARM_JOINTS`,
 * `GRIPPER`, `GRIPPER_CLOSED`, `GRIPPER_WIDTH`, `ARM_DOCK`, `ARM_DOCKED`): AOUT_double holds what
 * the robot sent, AIN_double what the device answered, both exact. A grab's pair is the
 * CObservationStereoImages (`BISIGHT`) just before its call, a device's refusal or failure the
 * CObservationComment (`DEVICE_FAULT`: its type, then its message) just before; the call record
 * comes last, so a recording cut anywhere holds whole calls only. */
#include <mrolr/geometry/BiSightHead.h>
#include <mrolr/hw/Devices.h>
#include <mrolr/io/ObservationLog.h>

#include <mrpt/obs/CObservation.h>

#include <exception>
#include <optional>
#include <string>
#include <vector>

namespace mrolr::mission
{
enum class CallKind
{
	BaseStep,       ///< request v1_mps, v2_mps, dt_s
	BaseOdometry,   ///< answer z, x, φ (m, rad), ticks right, ticks left, time_s, bumper
	HeadMove,       ///< request pan, tilt, verg_left, verg_right (rad); answer settle seconds
	HeadAngles,     ///< answer pan, tilt, verg_left, verg_right (rad)
	HeadGrab,       ///< answer pan, tilt, verg_left, verg_right, time_s, frame; the pair
	ArmMove,        ///< request d1 (mm), q1..q6 (deg)
	ArmJoints,      ///< answer d1 (mm), q1..q6 (deg)
	ArmGripper,     ///< request closed (1) or open (0)
	ArmGripperClosed,  ///< answer 1 or 0
	ArmGripperWidth,   ///< answer the jaws' distance (mm)
	ArmDock,        ///< request docked (1) or de-coupled (0)
	ArmDocked       ///< answer 1 or 0
};

/** A device's refusal or failure as recorded: the C++ type it threw and its message. */
struct DeviceFault
{
	std::string type, message;
};

/** One request and what the device answered (or the fault it raised instead). */
struct DeviceCall
{
	CallKind kind = CallKind::BaseStep;
	std::vector<double> request, answer;
	/** HeadGrab: the pair (as read back, its images still in their files: loadPair). */
	std::optional<hw::StereoImages> images;
	std::optional<DeviceFault> fault;
	double time_s = 0;  ///< the devices' clock when it was made (timestamps, for viewers)
};

/** Head angles as recorded values (pan, tilt, verg_left, verg_right) and back. */
std::vector<double> valuesOf(const geometry::HeadAngles& a);
geometry::HeadAngles anglesFrom(const std::vector<double>& v);

/** The sensor label of a call's record. */
const char* labelOf(CallKind kind);
/** The call of a sensor label, if it is one. */
std::optional<CallKind> callOfLabel(const std::string& label);
/** "head.moveTo(0.1, -0.3, 1.2, 1.2)": device, request and its values, for messages. */
std::string describe(CallKind kind, const std::vector<double>& request);

/** The fault a device raised, for the recording. */
DeviceFault faultOf(const std::exception& e);
/** Throws the exception @p f was recorded from: the same type, the same message. */
[[noreturn]] void rethrow(const DeviceFault& f);

/** The observations of @p call, in the order to write them (the pair, the fault, the call);
 * images go through @p log into its images folder as `BISIGHT_<index>_{left,right}.png`.
 * @p head gives the cameras' intrinsics and poses on the vehicle for the pair. */
std::vector<mrpt::obs::CObservation::Ptr> observationsOf(const DeviceCall& call, size_t index,
                                                         const geometry::BiSightHead& head,
                                                         const io::ObservationLogWriter& log);

/** What a recording holds for a replay: its device calls in order, and where a stop was
 * requested (the index of the call before which the mission's stop flag was raised). */
struct RecordedCalls
{
	std::vector<DeviceCall> calls;
	std::vector<size_t> stops_before;
	std::string torn;  ///< the reader's note when the file ended inside a record
	std::string path;  ///< the rawlog read
};

/** The device calls of the rawlog at @p path, images loaded (throws std::runtime_error naming the
 * file and record when a call record is malformed). Everything else in it (decisions, truth,
 * viewer observations) is skipped: a replay never reads it. */
RecordedCalls readDeviceCalls(const std::string& path);

/** A recorded pair (readDeviceCalls leaves its images in their files) with its pixels loaded. */
hw::StereoImages loadPair(const hw::StereoImages& recorded, const std::string& rawlog_path);

/** Sensor label of the comment that marks a stop request between two calls. */
inline constexpr const char* kStopLabel = "STOP_REQUESTED";
inline constexpr const char* kFaultLabel = "DEVICE_FAULT";

}  // namespace mrolr::mission
