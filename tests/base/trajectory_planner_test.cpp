#include <mrolr/base/TrajectoryPlanner.h>

#include <gtest/gtest.h>

#include <cmath>
#include <numeric>

using namespace mrolr::base;

TEST(TrajectoryPlanner, ThesisExampleOf1490mm)
{
	// 7.2.1: 1490 mm → 7 × 200 mm, 1 × 45 mm, 2 × 22.5 mm.
	const auto s = translationSteps(1.49, TrajectoryOptions{});
	ASSERT_EQ(s.size(), 10u);
	for (int i = 0; i < 7; ++i) EXPECT_DOUBLE_EQ(s[i], 0.2);
	EXPECT_NEAR(s[7], 0.045, 1e-12);
	EXPECT_NEAR(s[8], 0.0225, 1e-12);
	EXPECT_NEAR(s[9], 0.0225, 1e-12);
}

TEST(TrajectoryPlanner, StepsSumToTheDistanceAndNeverExceedAFullStep)
{
	const TrajectoryOptions o;
	for (double d : {0.0, 0.01, 0.031, 0.2, 0.25, 0.4, 1.0, 3.333})
	{
		const auto s = translationSteps(d, o);
		EXPECT_NEAR(std::accumulate(s.begin(), s.end(), 0.0), d, 1e-12) << d;
		for (double x : s)
		{
			EXPECT_LE(x, o.step_length_m + 1e-12);
		}
		// The last step is a whole step or a remainder under min_step_m.
		if (s.size() > 1)
		{
			EXPECT_TRUE(s.back() < o.min_step_m || std::abs(s.back() - o.step_length_m) < 1e-12)
			    << d;
		}
	}
	EXPECT_EQ(translationSteps(0.4, o).size(), 2u);  // whole steps are not halved
}

TEST(TrajectoryPlanner, NoiseFreeLegReachesTheWaypoint)
{
	const LabmateModel model;
	TrajectoryOptions o;
	o.max_rotation_step_deg = 30;
	const Eigen::Vector3d from(0.2, -0.3, 2.5), to(1.7, 0.9, -0.4);
	Eigen::Vector3d x = from;
	const auto plan = planLeg(from, to, model, o);
	for (const auto& step : plan)
	{
		x = model.move(x, step.u);
		if (step.kind == PlannedStep::Kind::Rotate)
		{
			EXPECT_LE(std::abs(step.amount), 30 * M_PI / 180 + 1e-12);
		}
	}
	EXPECT_NEAR((x - to).head<2>().norm(), 0, 1e-12);
	EXPECT_NEAR(wrapAngle(x[2] - to[2]), 0, 1e-12);
	// The first step turns towards the waypoint, the middle ones translate.
	EXPECT_EQ(plan.front().kind, PlannedStep::Kind::Rotate);
	EXPECT_EQ(plan.back().kind, PlannedStep::Kind::Rotate);
}

TEST(TrajectoryPlanner, WrapAngleRange)
{
	EXPECT_NEAR(wrapAngle(3 * M_PI / 2), -M_PI / 2, 1e-15);
	EXPECT_NEAR(wrapAngle(-M_PI), M_PI, 1e-15);
	EXPECT_NEAR(wrapAngle(0.3 + 8 * M_PI), 0.3, 1e-12);
}
