#pragma once
/** The simulated lab a mission runs in: the true base (sim::SimBase), the objects' true poses, the
 * head that renders the lab's stereo pairs and the docked RTX arm (sim::SimArm). These are the
 * devices of `driver = sim`, and what the device emulators serve on pseudo-terminals for
 * `driver = serial` (SerialEmulation), so in both cases the mission's simulated perception
 * (landmark angles, scene wire-frames, docs/mission.md) reads the same truth. Poses in W, metres.
 */
#include <mrolr/hw/Devices.h>
#include <mrolr/mission/MissionOptions.h>
#include <mrolr/sim/SimArm.h>
#include <mrolr/sim/SimBase.h>

#include <Eigen/Geometry>
#include <map>
#include <memory>
#include <string>

namespace mrolr::mission
{
class SimulatedLab
{
 public:
	/** The base starts at the route's first waypoint, the objects where the world places them. */
	explicit SimulatedLab(const MissionOptions& o);
	~SimulatedLab();
	SimulatedLab(const SimulatedLab&) = delete;
	SimulatedLab& operator=(const SimulatedLab&) = delete;

	sim::SimBase& base() { return base_; }
	/** Moves take `[search] head_move_time_s`; grab() renders the lab (sim::StereoRenderer, built
	 * at the first grab) from the true head pose. */
	hw::HeadDevice& head() { return *head_; }
	sim::SimArm& arm() { return *arm_; }

	/** True vehicle pose (z, x, φ) in W. */
	Eigen::Vector3d truePose() const { return base_.truePose(); }
	/** True head centre C0 in W (m). */
	Eigen::Isometry3d trueC0() const;
	/** Instance name → true T_OinW (m); the arm moves the one it holds. */
	std::map<std::string, Eigen::Isometry3d>& objectPoses() { return poses_; }
	/** Simulated docking: the arm base now stands at the known [arm_mount] T_C0inA from the true
	 * head centre (the arm's joints are kept). */
	void dockArm();

 private:
	const MissionOptions& o_;
	sim::SimBase base_;
	std::map<std::string, Eigen::Isometry3d> poses_;
	Eigen::Isometry3d T_AinW_ = Eigen::Isometry3d::Identity();
	std::unique_ptr<hw::HeadDevice> head_;
	std::unique_ptr<sim::SimArm> arm_;
};

}  // namespace mrolr::mission
