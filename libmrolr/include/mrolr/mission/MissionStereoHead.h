#pragma once
/** The mission's head device (hw::HeadDevice: the simulated lab's rendering head, or a serial head
 * whose pairs come from the frame grabber) seen as the vision area's vision::StereoHeadDevice, so
 * that navigation can measure its features in the images (`[navigation] measurement_source =
 * images`, docs/mission.md). Grabbing is timed apart: rendering is the simulator's time, not the
 * robot's compute. */
#include <mrolr/hw/Devices.h>
#include <mrolr/vision/StereoHeadDevice.h>

namespace mrolr::mission
{
class MissionStereoHead : public vision::StereoHeadDevice
{
 public:
	explicit MissionStereoHead(hw::HeadDevice& head) : head_(head) {}
	/** Moves the joints (radians). */
	void moveTo(const geometry::HeadAngles& angles) override;
	geometry::HeadAngles angles() const override { return head_.angles(); }
	/** An 8-bit greyscale pair (CV_8UC1) at the current angles. */
	vision::StereoImages grab() override;
	/** Wall seconds spent in grab() so far (rendering in simulation). */
	double grabSeconds() const { return grab_s_; }
	/** Pairs grabbed so far. */
	int grabs() const { return grabs_; }

 private:
	hw::HeadDevice& head_;
	double grab_s_ = 0;
	int grabs_ = 0;
};

}  // namespace mrolr::mission
