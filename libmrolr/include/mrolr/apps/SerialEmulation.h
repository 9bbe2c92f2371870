#pragma once
/** The simulated lab's devices served as a real robot's are: the base, head and arm on
 * pseudo-terminals (hw_serial::PtyEmulator around hw_serial::BaseHandler, HeadHandler, ArmHandler) and the head's
 * stereo camera on a local TCP socket (hw_serial::CameraServer), so that a mission with `driver = serial`
 * and `[device.camera] driver = socket` runs through real I/O (`mrolr-mission --serial-emulation`,
 * `mrolr-serial emulate`; docs/mission.md "Hardware path"). Faults can be injected per serial
 * device, also while the mission runs. */
#include <mrolr/hw_serial/CameraServer.h>
#include <mrolr/hw_serial/DeviceEmulator.h>
#include <mrolr/mission/MissionOptions.h>
#include <mrolr/sim/Lab.h>

#include <memory>

namespace mrolr::apps
{
class SerialEmulation
{
 public:
	/** Starts serving @p lab's base, head and arm (it must outlive this object), each with
	 * @p faults. */
	explicit SerialEmulation(sim::Lab& lab, const hw_serial::FaultOptions& faults = {});
	~SerialEmulation();
	/** Switches every device of @p o to `driver = serial` on its pseudo-terminal and the camera
	 * to the socket; link timeouts and retries already configured for serial are kept,
	 * otherwise @p defaults are used. */
	void useIn(mission::MissionOptions& o, const hw_serial::LinkOptions& defaults = {}) const;
	hw_serial::PtyEmulator& base() { return *base_; }
	hw_serial::PtyEmulator& head() { return *head_; }
	hw_serial::PtyEmulator& arm() { return *arm_; }
	hw_serial::CameraServer& camera() { return *camera_; }

 private:
	hw_serial::BaseHandler base_handler_;
	hw_serial::HeadHandler head_handler_;
	hw_serial::ArmHandler arm_handler_;
	std::unique_ptr<hw_serial::PtyEmulator> base_, head_, arm_;
	std::unique_ptr<hw_serial::CameraServer> camera_;
};

}  // namespace mrolr::apps
