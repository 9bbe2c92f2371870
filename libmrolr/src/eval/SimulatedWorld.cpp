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
    : m_world(world),
      m_setup(setup),
      m_model(trueMotion(setup)),
      m_rng(seed),
      m_first_seen(world.landmarks.size())
{
}

void SimulatedWorld::move(const base::WheelControl& u)
{
	std::normal_distribution<double> n(0, 1);
	const double f = m_setup.sim.true_velocity_noise_fraction;
	base::WheelControl t = u;
	t.v1_mps += f * std::abs(u.v1_mps) * n(m_rng);
	t.v2_mps += f * std::abs(u.v2_mps) * n(m_rng);
	if (m_slip_left == 0 &&
	    std::uniform_real_distribution<double>(0, 1)(m_rng) < m_setup.sim.slip_burst_probability)
	{
		m_slip_left = m_setup.sim.slip_burst_length_steps;
		m_slip_wheel = std::uniform_int_distribution<int>(0, 1)(m_rng);
	}
	if (m_slip_left > 0)
	{
		(m_slip_wheel == 0 ? t.v1_mps : t.v2_mps) *= 1 - m_setup.sim.slip_fraction;
		--m_slip_left;
	}
	m_pose = m_model.move(m_pose, t);
}

Eigen::Vector3d SimulatedWorld::trueAngles(size_t k) const
{
	return slam::predictMeasurement(m_pose, m_world.landmarks.at(k).p_LinW,
	                                m_setup.slam.head.constants);
}

bool SimulatedWorld::visible(size_t k) const
{
	const auto& lm = m_world.landmarks.at(k);
	const auto& head = m_setup.slam.head.constants;
	if ((lm.p_LinW - slam::headCentreInW(m_pose, head)).norm() > m_setup.sim.max_range_m)
		return false;
	if (lm.known || !m_first_seen[k])
		return slam::headCanFixate(m_pose, lm.p_LinW, m_setup.slam.head) ==
		       slam::Visibility::Visible;
	return slam::assessVisibility(m_pose, lm.p_LinW, *m_first_seen[k], m_setup.slam) ==
	       slam::Visibility::Visible;
}

Eigen::Vector3d SimulatedWorld::measure(size_t k, bool allow_outlier, bool& outlier)
{
	std::normal_distribution<double> n(0, 1);
	const auto& s = m_setup.sim;
	Eigen::Vector3d h = trueAngles(k);
	h += Eigen::Vector3d(s.true_std_pan_rad * n(m_rng), s.true_std_elevation_rad * n(m_rng),
	                     s.true_std_vergence_rad * n(m_rng));
	std::uniform_real_distribution<double> u(0, 1);
	outlier = allow_outlier && u(m_rng) < s.outlier_fraction;
	if (outlier)
	{
		for (int c = 0; c < 2; ++c)
			h[c] += (u(m_rng) < 0.5 ? -1 : 1) * (0.5 + 0.5 * u(m_rng)) * s.outlier_magnitude_rad;
	}
	return h;
}

void SimulatedWorld::markFirstSeen(size_t k)
{
	m_first_seen.at(k) = slam::headCentreInW(m_pose, m_setup.slam.head.constants);
}

size_t SimulatedWorld::landmarkIndex(const std::string& name) const
{
	for (size_t k = 0; k < m_world.landmarks.size(); ++k)
		if (m_world.landmarks[k].name == name) return k;
	throw std::out_of_range("no landmark called '" + name + "'");
}

}  // namespace mrolr::eval::detail
