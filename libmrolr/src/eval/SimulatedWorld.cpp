#include "SimulatedWorld.h"

#include <mrolr/slam/FeatureVisibility.h>

#include <stdexcept>

namespace mrolr::eval::detail
{
namespace
{
base::LabmateOptions trueMotion(const SimulationSetup& s)
{
	base::LabmateOptions o = s.labmate;
	o.velocity_noise_fraction = s.sim.true_velocity_noise_fraction;
	return o;
}
}  // namespace

SimulatedWorld::SimulatedWorld(const world::World& world, const SimulationSetup& setup,
                               uint64_t seed)
    : world_(world),
      setup_(setup),
      model_(trueMotion(setup)),
      rng_(seed),
      first_seen_(world.landmarks.size())
{
}

void SimulatedWorld::move(const base::WheelControl& u)
{
	std::normal_distribution<double> n(0, 1);
	const double f = setup_.sim.true_velocity_noise_fraction;
	base::WheelControl t = u;
	t.v1_mps += f * std::abs(u.v1_mps) * n(rng_);
	t.v2_mps += f * std::abs(u.v2_mps) * n(rng_);
	if (slip_left_ == 0 &&
	    std::uniform_real_distribution<double>(0, 1)(rng_) < setup_.sim.slip_burst_probability)
	{
		slip_left_ = setup_.sim.slip_burst_length_steps;
		slip_wheel_ = std::uniform_int_distribution<int>(0, 1)(rng_);
	}
	if (slip_left_ > 0)
	{
		(slip_wheel_ == 0 ? t.v1_mps : t.v2_mps) *= 1 - setup_.sim.slip_fraction;
		--slip_left_;
	}
	pose_ = model_.move(pose_, t);
}

Eigen::Vector3d SimulatedWorld::trueAngles(size_t k) const
{
	return slam::predictMeasurement(pose_, world_.landmarks.at(k).p_LinW,
	                                setup_.slam.head.constants);
}

bool SimulatedWorld::visible(size_t k) const
{
	const auto& lm = world_.landmarks.at(k);
	const auto& head = setup_.slam.head.constants;
	if ((lm.p_LinW - slam::headCentreInW(pose_, head)).norm() > setup_.sim.max_range_m)
		return false;
	if (lm.known || !first_seen_[k])
		return slam::headCanFixate(pose_, lm.p_LinW, setup_.slam.head) ==
		       slam::Visibility::Visible;
	return slam::assessVisibility(pose_, lm.p_LinW, *first_seen_[k], setup_.slam) ==
	       slam::Visibility::Visible;
}

Eigen::Vector3d SimulatedWorld::measure(size_t k, bool allow_outlier, bool& outlier)
{
	std::normal_distribution<double> n(0, 1);
	const auto& s = setup_.sim;
	Eigen::Vector3d h = trueAngles(k);
	h += Eigen::Vector3d(s.true_std_pan_rad * n(rng_), s.true_std_elevation_rad * n(rng_),
	                     s.true_std_vergence_rad * n(rng_));
	std::uniform_real_distribution<double> u(0, 1);
	outlier = allow_outlier && u(rng_) < s.outlier_fraction;
	if (outlier)
	{
		for (int c = 0; c < 2; ++c)
			h[c] += (u(rng_) < 0.5 ? -1 : 1) * (0.5 + 0.5 * u(rng_)) * s.outlier_magnitude_rad;
	}
	return h;
}

void SimulatedWorld::markFirstSeen(size_t k)
{
	first_seen_.at(k) = slam::headCentreInW(pose_, setup_.slam.head.constants);
}

size_t SimulatedWorld::landmarkIndex(const std::string& name) const
{
	for (size_t k = 0; k < world_.landmarks.size(); ++k)
		if (world_.landmarks[k].name == name) return k;
	throw std::out_of_range("no landmark called '" + name + "'");
}

}  // namespace mrolr::eval::detail
