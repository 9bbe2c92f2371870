#pragma once
/** Device interfaces of the robot (DESIGN.md "hw"): the simulator (area sim) and the serial drivers
 * implement them, so the mission cannot tell the two apart. Frames and units as in the thesis:
 * vehicle pose (z, x, φ) in W, head angles in radians, arm joints d1 in mm and q1..q6 in degrees.
 */

#include <mrolr/base/LabmateModel.h>
#include <mrolr/geometry/BiSightHead.h>

#include <mrpt/img/CImage.h>

#include <array>
#include <stdexcept>
#include <cstdint>

namespace mrolr::hw
{
/** A device can no longer answer: the mission stops where it is, keeping what it recorded. The
 * serial drivers throw it when a line goes dead (hw_serial/SerialError.h), a replayed recording
 * when it has no answer for the request (ReplayDivergence). */
class DeviceFailure : public std::runtime_error
{
 public:
	using std::runtime_error::runtime_error;
};

/** A replay was asked for something its recording does not hold (docs/mission.md "Replay"): what()
 * names the call (its index and device time), the device and the request asked for, and what the
 * recording has there. A replay never invents an answer. */
class ReplayDivergence : public DeviceFailure
{
 public:
	using DeviceFailure::DeviceFailure;
};

/** Odometry of the base: the pose integrated from the wheel encoders, and the raw encoder counts.
 */
struct Odometry
{
	Eigen::Vector3d xv_zxphi = Eigen::Vector3d::Zero();  ///< dead-reckoned (z, x, φ) in W
	long ticks_right = 0;                                ///< encoder of wheel 1 (v1)
	long ticks_left = 0;                                 ///< encoder of wheel 2 (v2)
	double time_s = 0;
	/** The bumper is pressed: the base ran into something and stopped there (it stays pressed
	 * while the base stands against it). */
	bool bumper = false;
};

/** The Labmate base (thesis 4.2.6): wheel-velocity steps and encoder odometry. */
class BaseDevice
{
 public:
	virtual ~BaseDevice() = default;
	/** Executes one control step (blocking for u.dt_s of robot time). */
	virtual void step(const base::WheelControl& u) = 0;
	virtual Odometry odometry() const = 0;
};

/** A stereo pair from the head's cameras, with the joint angles it was taken at. */
struct StereoImages
{
	mrpt::img::CImage left, right;
	geometry::HeadAngles angles;
	double time_s = 0;
	uint64_t frame = 0;  ///< the camera's frame counter: 0, 1, 2, … per grab
};

/** The BiSight head (thesis 4.2.2): joint moves with speed limits and settling, stereo grabs. */
class HeadDevice
{
 public:
	virtual ~HeadDevice() = default;
	/** Moves to @p target (throws geometry::FixationError beyond a joint limit); returns the time
	 * in seconds until the joints have settled. */
	virtual double moveTo(const geometry::HeadAngles& target) = 0;
	virtual geometry::HeadAngles angles() const = 0;
	virtual StereoImages grab() = 0;
};

/** The model-building turntable (thesis 6.1, B.2.1) before fixed calibrated cameras. */
class TurntableDevice
{
 public:
	virtual ~TurntableDevice() = default;
	/** Rotates by @p step_deg (positive counter-clockwise seen from above, about the table axis).
	 */
	virtual void rotateBy(double step_deg) = 0;
	virtual double angleDeg() const = 0;
	virtual StereoImages grab() = 0;
};

/** Joint vector of the UMI RTX arm: d1 (mm, the vertical column), q1..q6 (degrees). */
using ArmJoints = std::array<double, 7>;

/** The arm stopped against something before it reached the commanded joints (its motors stalled);
 * it stands at the last pose it reached. */
struct ArmBlocked : std::runtime_error
{
	using std::runtime_error::runtime_error;
};

/** The UMI RTX arm (thesis 6.7): joint moves within the workspace limits and the gripper. */
class ArmDevice
{
 public:
	virtual ~ArmDevice() = default;
	/** Moves to @p joints; throws std::out_of_range naming the joint if a limit is exceeded, and
	 * ArmBlocked when the arm meets something on the way. */
	virtual void moveTo(const ArmJoints& joints) = 0;
	virtual ArmJoints joints() const = 0;
	virtual void setGripper(bool closed) = 0;
	virtual bool gripperClosed() const = 0;
	/** Distance between the jaws (mm) as the gripper's encoder reports it: the full opening when
	 * open, about 0 when closed on nothing, the object's width when closed on one. The robot
	 * decides from this whether it holds something; no device tells it what it holds. */
	virtual double gripperWidthMm() const = 0;
	/** Docks the arm's platform with the base (true) or de-couples it (false). Thesis 7.0: the
	 * RTX on its caster platform is docked with MROLR once the object is found and de-coupled
	 * before the drive home, so the head does not carry the arm in its view while it navigates.
	 * The arm moves and grips only while docked; a device may refuse to de-couple an arm that
	 * holds something. Refusals throw (std::logic_error in process, SerialDeviceError on a line),
	 * naming what was refused. */
	virtual void dock(bool docked) = 0;
	virtual bool docked() const = 0;
};

}  // namespace mrolr::hw
