// controlFromOdometry inverts the Labmate model (eqs 5.1-5.7): replaying the control from the
// odometry increment lands on the recorded pose, for arcs, straight moves and turns in place.
#include <mrolr/apps/OdometryControl.h>

#include <gtest/gtest.h>

#include <random>

using mrolr::apps::controlFromOdometry;
using mrolr::base::LabmateModel;
using mrolr::base::WheelControl;

TEST(OdometryControl, ReplayedControlReachesTheRecordedPose)
{
	const LabmateModel model;
	const double D1 = model.options().wheel_half_separation_m;
	std::mt19937 rng(5);
	std::uniform_real_distribution<double> v(-0.3, 0.3), pose(-3, 3), dt(0.5, 4);
	for (int trial = 0; trial < 300; ++trial)
	{
		WheelControl u{v(rng), v(rng), dt(rng)};
		if (trial % 3 == 1) u.v2_mps = u.v1_mps;   // straight
		if (trial % 3 == 2) u.v2_mps = -u.v1_mps;  // in place
		const Eigen::Vector3d from(pose(rng), pose(rng), pose(rng));
		const Eigen::Vector3d to = model.move(from, u);
		if (std::abs(model.turnAngle(u)) >= M_PI) continue;  // beyond half a turn θ is ambiguous
		const WheelControl back = controlFromOdometry(from, to, u.dt_s, D1);
		EXPECT_NEAR(back.v1_mps, u.v1_mps, 1e-9) << trial;
		EXPECT_NEAR(back.v2_mps, u.v2_mps, 1e-9) << trial;
		EXPECT_LT((model.move(from, back) - to).norm(), 1e-9) << trial;
	}
}

TEST(OdometryControl, NonPositiveTimeStepIsAnError)
{
	EXPECT_THROW(controlFromOdometry({0, 0, 0}, {1, 0, 0}, 0, 0.3), std::invalid_argument);
	EXPECT_THROW(controlFromOdometry({0, 0, 0}, {1, 0, 0}, -1, 0.3), std::invalid_argument);
}
