#pragma once
/** The simulated Labmate base (thesis 4.2.6, 5.3): the wheels turn as commanded plus the
 * wheel-velocity noise of eq 5.13, and the optical encoders count what the wheels really turned;
 * the vehicle then moves by the Labmate model (eqs 5.4–5.7) with those wheel velocities, except
 * during bursts of wheel slip, when the left wheel's turning moves the vehicle less than the
 * encoder says. So odometry drifts from the truth by the slip only, as a real base does, while
 * predicting from the commands drifts by the velocity noise too.
 *
 * With a collision world (setCollisionWorld) the true motion of a step stops at the last pose where
 * the footprint touches nothing; the wheels stall there (the encoders count the wheel travel up to
 * the contact only) and the bumper is pressed while the base stands against the obstacle. */

#include <mrolr/base/LabmateModel.h>
#include <mrolr/hw/Devices.h>
#include <mrolr/sim/Collisions.h>

#include <mrpt/config/CConfigFileBase.h>

#include <iosfwd>
#include <memory>
#include <optional>
#include <random>

namespace mrolr::sim
{
/** Section [sim_base] of config/sim.ini. */
struct SimBaseOptions
{
	double ticks_per_m = 20000;      ///< encoder counts per metre of wheel travel
	double slip_probability = 0.02;  ///< chance per step that a slip burst starts
	int slip_burst_steps = 3;        ///< steps a burst lasts
	double slip_fraction = 0.3;      ///< fraction of the left wheel's travel lost while slipping
	unsigned seed = 1;
	/** `footprint_length_m`, `footprint_width_m`, `footprint_offset_m` (all optional). */
	Footprint footprint;
	/** Optional fault for tests (`kick_after_s`, `kick_deg`): the first turn in place after this
	 * base time turns the base by kick_deg more than its wheels did (a slipped turn, invisible
	 * to the encoders); < 0 (default): never. */
	double kick_after_s = -1;
	double kick_deg = 0;

	void loadFromConfigFile(const mrpt::config::CConfigFileBase& cfg, const std::string& section);
	void dump(std::ostream& out) const;
};

class SimBase : public hw::BaseDevice
{
 public:
	SimBase(const base::LabmateModel& model, const SimBaseOptions& options,
	        const Eigen::Vector3d& start_zxphi = Eigen::Vector3d::Zero());

	void step(const base::WheelControl& u) override;
	hw::Odometry odometry() const override { return odo_; }

	/** Makes the base collide with @p world from now on (nullptr: drive through everything
	 * again). Throws std::invalid_argument, naming what it overlaps, if the base's true pose
	 * already overlaps a wall, table or obstacle. */
	void setCollisionWorld(std::shared_ptr<const CollisionWorld> world);
	/** The latest contact: a step stopped by it, or a step that ended within the bumper's travel
	 * of something (free_fraction 1); kept after the bumper releases. nullopt until the base
	 * first touches something. */
	const std::optional<Contact>& lastContact() const { return last_contact_; }
	/** Steps stopped by a contact so far. */
	int contactsSoFar() const { return contacts_total_; }

	/** Ground truth (z, x, φ) in W. */
	const Eigen::Vector3d& truePose() const { return true_; }
	/** True while a slip burst is under way. */
	bool slipping() const { return slip_left_ > 0; }
	int slipStepsSoFar() const { return slip_steps_total_; }

	/** How close the footprint must come to something for the bumper to press (m). */
	static constexpr double kBumperTravel_m = 0.01;

 private:
	base::WheelControl turnedWheels(const base::WheelControl& u);
	base::WheelControl slipped(const base::WheelControl& turned);
	double moveTruth(const base::WheelControl& moved);
	void countEncoders(const base::WheelControl& turned, double stall_fraction);
	long countTicks(double travel_m, double& residual);

	base::LabmateModel model_;
	SimBaseOptions options_;
	std::mt19937 rng_;
	Eigen::Vector3d true_;
	hw::Odometry odo_;
	double residual_right_ = 0, residual_left_ = 0;
	int slip_left_ = 0, slip_steps_total_ = 0;
	bool kicked_ = false;
	std::shared_ptr<const CollisionWorld> collisions_;
	std::optional<Contact> last_contact_;
	int contacts_total_ = 0;
};

}  // namespace mrolr::sim
