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

	const Eigen::Vector3d& pose() const { return m_pose; }
	void setPose(const Eigen::Vector3d& x_v) { m_pose = x_v; }
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
	const world::World& m_world;
	const SimulationSetup& m_setup;
	base::LabmateModel m_model;
	std::mt19937_64 m_rng;
	Eigen::Vector3d m_pose = Eigen::Vector3d::Zero();
	int m_slip_left = 0;
	int m_slip_wheel = 0;
	std::vector<std::optional<Eigen::Vector3d>> m_first_seen;
};

}  // namespace mrolr::eval::detail
