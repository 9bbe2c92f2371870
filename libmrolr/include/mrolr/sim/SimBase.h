#pragma once
/** The simulated Labmate base: the true pose moves by the Labmate model (thesis 5.3, eqs 5.4–5.7)
 * with wheel-velocity noise (eq 5.13) and bursts of wheel slip, while the encoders count what the
 * wheels turned, so odometry drifts from the truth as a real base does. */

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
	double slip_fraction = 0.3;      ///< fraction of one wheel's travel lost while slipping
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
	base::WheelControl trueControl(const base::WheelControl& u);
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
