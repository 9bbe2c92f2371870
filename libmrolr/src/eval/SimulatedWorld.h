#pragma once
// The true side of the simulation: the real vehicle pose, wheel slip, and what the head really
// measures. Private to the eval library.

#include <mrolr/eval/EkfSimulation.h>

#include <optional>
#include <random>

namespace mrolr::eval::detail
{
class SimulatedWorld
{
 public:
	SimulatedWorld(const world::World& world, const SimulationSetup& setup, uint64_t seed);

	const Eigen::Vector3d& pose() const { return pose_; }
	void setPose(const Eigen::Vector3d& x_v) { pose_ = x_v; }
	/** Moves the true vehicle by @p u with wheel noise and (in a burst) wheel slip. */
	void move(const base::WheelControl& u);
	/** True when landmark @p k can be found and fixated from the true pose now. */
	bool visible(size_t k) const;
	/** True ideal-head angles of landmark @p k from the true pose. */
	Eigen::Vector3d trueAngles(size_t k) const;
	/** A noisy measurement of landmark @p k; sets @p outlier when it is an injected outlier. */
	Eigen::Vector3d measure(size_t k, bool allow_outlier, bool& outlier);
	/** Remembers the true head position when landmark @p k is first mapped (5.2.1). */
	void markFirstSeen(size_t k);
	/** Index of the landmark called @p name; throws std::out_of_range when there is none. */
	size_t landmarkIndex(const std::string& name) const;

 private:
	const world::World& world_;
	const SimulationSetup& setup_;
	base::LabmateModel model_;
	std::mt19937_64 rng_;
	Eigen::Vector3d pose_ = Eigen::Vector3d::Zero();
	int slip_left_ = 0;
	int slip_wheel_ = 0;
	std::vector<std::optional<Eigen::Vector3d>> first_seen_;
};

}  // namespace mrolr::eval::detail
