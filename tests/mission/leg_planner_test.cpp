// Mission legs: a goal a short way behind is reached backwards, with turns under 90 degrees.
#include <mrolr/mission/Navigator.h>

#include <gtest/gtest.h>

#include <cmath>

using namespace mrolr;

namespace
{
/** The noise-free pose after executing @p plan from @p x (z, x, φ in W). */
Eigen::Vector3d execute(const base::LabmateModel& m, Eigen::Vector3d x,
                        const std::vector<base::PlannedStep>& plan)
{
	for (const auto& s : plan) x = m.move(x, s.u);
	return x;
}

double largestTurnDeg(const std::vector<base::PlannedStep>& plan)
{
	double total = 0, largest = 0;
	for (const auto& s : plan)
		if (s.kind == base::PlannedStep::Kind::Rotate)
			total += s.amount;
		else
			largest = std::max(largest, std::abs(total)), total = 0;
	return std::max(largest, std::abs(total)) * 180 / M_PI;
}

bool anyTranslation(const std::vector<base::PlannedStep>& plan, bool backwards)
{
	for (const auto& s : plan)
		if (s.kind == base::PlannedStep::Kind::Translate && (s.amount < 0) == backwards)
			return true;
	return false;
}
}  // namespace

TEST(MissionLeg, GoalShortlyBehindIsReachedBackwardsWithSmallTurns)
{
	const base::LabmateModel m;
	base::TrajectoryOptions o;
	for (const Eigen::Vector3d& goal :
	     {Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(0.1, -0.3, 0.4), Eigen::Vector3d(0.3, 0.3, -1)})
	{
		const Eigen::Vector3d from(0.5, 0.02, 0.05);
		const auto plan = mission::planMissionLeg(from, goal, m, o, 0.6);
		EXPECT_TRUE(anyTranslation(plan, true));
		EXPECT_FALSE(anyTranslation(plan, false));
		EXPECT_LT(largestTurnDeg(plan), 90.0 + 1e-9);  // the head never turns its back on the map
		const Eigen::Vector3d end = execute(m, from, plan);
		EXPECT_LT((end.head<2>() - goal.head<2>()).norm(), 1e-9);
		EXPECT_NEAR(base::wrapAngle(end.z() - goal.z()), 0, 1e-9);
	}
}

TEST(MissionLeg, GoalsAheadOrFarBehindUseTheThesisLeg)
{
	const base::LabmateModel m;
	base::TrajectoryOptions o;
	const Eigen::Vector3d from(0.5, 0, 0);
	for (const Eigen::Vector3d& goal : {Eigen::Vector3d(1.0, 0.2, 0), Eigen::Vector3d(-0.5, 0, 0)})
	{
		const auto plan = mission::planMissionLeg(from, goal, m, o, 0.6);
		const auto thesis = base::planLeg(from, goal, m, o);
		ASSERT_EQ(plan.size(), thesis.size());
		for (size_t i = 0; i < plan.size(); ++i) EXPECT_EQ(plan[i].amount, thesis[i].amount);
		EXPECT_FALSE(anyTranslation(plan, true));
	}
	// reverse_max_m = 0 never reverses
	EXPECT_FALSE(anyTranslation(mission::planMissionLeg(from, {0.3, 0, 0}, m, o, 0), true));
}
