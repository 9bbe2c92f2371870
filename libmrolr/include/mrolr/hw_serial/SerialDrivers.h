#pragma once
/** Serial drivers of the Labmate base, the BiSight head and the RTX arm: the hw:: device interfaces
 * over the line protocols of DeviceProtocols.h (docs/serial.md). Each constructor asks the device
 * `ID?` and throws SerialDeviceError (Refused) if another device answers on the port. Every call
 * may throw SerialDeviceError (timeout, garbage, disconnect) naming device and port. */

#include <mrolr/hw/Devices.h>
#include <mrolr/hw_serial/SerialClient.h>

#include <functional>
#include <memory>

namespace mrolr::hw_serial
{
/** The Labmate base over serial: `STEP` blocks until the device has executed the step. */
class SerialBase : public hw::BaseDevice
{
 public:
	explicit SerialBase(std::unique_ptr<SerialClient> client);
	void step(const base::WheelControl& u) override;
	hw::Odometry odometry() const override;

 private:
	std::unique_ptr<SerialClient> client_;
};

/** Where the head's stereo pairs come from: the cameras are not on the serial line (on the robot
 * they are read by a frame grabber), so the driver is given a grabber function. */
using ImageSource = std::function<hw::StereoImages()>;

/** The BiSight head over serial: joint moves and angles on the line; grab() calls the injected
 * image source and stamps the pair with the joint angles read back from the head. */
class SerialHead : public hw::HeadDevice
{
 public:
	SerialHead(std::unique_ptr<SerialClient> client, ImageSource images);
	/** Throws geometry::FixationError when the head refuses a target beyond a joint limit. */
	double moveTo(const geometry::HeadAngles& target) override;
	geometry::HeadAngles angles() const override;
	/** Throws std::logic_error when no image source was given. */
	hw::StereoImages grab() override;

 private:
	std::unique_ptr<SerialClient> client_;
	ImageSource images_;
};

/** The UMI RTX arm over serial. */
class SerialArm : public hw::ArmDevice
{
 public:
	explicit SerialArm(std::unique_ptr<SerialClient> client);
	/** Throws std::out_of_range (the device's text) when the arm refuses a joint limit. */
	void moveTo(const hw::ArmJoints& joints) override;
	hw::ArmJoints joints() const override;
	void setGripper(bool closed) override;
	bool gripperClosed() const override;
	double gripperWidthMm() const override;
	/** `DOCK 1` / `DOCK 0`; a refusal is a SerialDeviceError (refused) with the device's text. */
	void dock(bool docked) override;
	bool docked() const override;

 private:
	std::unique_ptr<SerialClient> client_;
};

}  // namespace mrolr::hw_serial
