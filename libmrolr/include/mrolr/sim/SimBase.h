#pragma once
/** The simulated Labmate base (thesis 4.2.6, 5.3): the wheels turn as commanded plus the
 * wheel-velocity noise of eq 5.13, and the optical encoders count what the wheels really turned;
 * the vehicle then moves by the Labmate model (eqs 5.4–5.7) with those wheel velocities, except
 * during bursts of wheel slip, when the left wheel's turning moves the vehicle less than the
 * encoder says. So odometry drifts from the truth by the slip only, as a real base does, while
 * predicting from the commands drifts by the velocity noise too. */

#include <mrolr/base/LabmateModel.h>
#include <mrolr/hw/Devices.h>

#include <mrpt/config/CConfigFileBase.h>

#include <iosfwd>
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

	/** Ground truth (z, x, φ) in W. */
	const Eigen::Vector3d& truePose() const { return true_; }
	/** True while a slip burst is under way. */
	bool slipping() const { return slip_left_ > 0; }
	int slipStepsSoFar() const { return slip_steps_total_; }

 private:
	base::WheelControl turnedWheels(const base::WheelControl& u);
	base::WheelControl slipped(const base::WheelControl& turned);
	void countEncoders(const base::WheelControl& turned);
	long countTicks(double travel_m, double& residual);

	base::LabmateModel model_;
	SimBaseOptions options_;
	std::mt19937 rng_;
	Eigen::Vector3d true_;
	hw::Odometry odo_;
	double residual_right_ = 0, residual_left_ = 0;
	int slip_left_ = 0, slip_steps_total_ = 0;
};

}  // namespace mrolr::sim
