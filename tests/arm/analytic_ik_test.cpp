// The analytic IK: FK → IK → FK on 10 000 random reachable poses, both elbow configurations, and
// unreachable or out-of-limit requests with errors naming the limit.
#include "ArmTestUtil.h"

#include <mrolr/arm/AnalyticIk.h>
#include <mrolr/arm/ArmError.h>
#include <mrolr/arm/GripperPose.h>
#include <mrolr/arm/RtxKinematics.h>

#include <mrpt/core/bits_math.h>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

using namespace mrolr::arm;
using ::testing::HasSubstr;

namespace
{
bool sameJoints(const RtxJoints& a, const RtxJoints& b, double tol)
{
	if (std::abs(a.d1_mm - b.d1_mm) > tol) return false;
	for (size_t i = 0; i < 6; ++i)
		if (std::abs(a.q_rad[i] - b.q_rad[i]) > tol) return false;
	return true;
}
}  // namespace

TEST(ArmAnalyticIk, RoundTripOnTenThousandRandomReachablePoses)
{
	std::mt19937 rng(42);
	const RtxKinematics kin;
	const AnalyticIk ik;
	size_t total = 0, with_both_elbows = 0;
	for (int n = 0; n < 10000; ++n)
	{
		const RtxJoints j = test::randomReachableJoints(rng);
		const Eigen::Isometry3d T = kin.T06(j);
		const IkResult r = ik.solve(T);
		ASSERT_FALSE(r.solutions.empty()) << "pose " << n << ": " << r.reason();
		bool found = false, left = false, right = false;
		for (const auto& s : r.solutions)
		{
			const Eigen::Isometry3d Ts = kin.T06(s.joints);
			ASSERT_LT(test::positionError(Ts, T), 1e-6) << "pose " << n;
			ASSERT_LT(test::rotationError(Ts, T), 1e-9) << "pose " << n;
			ASSERT_TRUE(limitViolation(s.counts, kin.options()).empty());
			found = found || sameJoints(s.joints, j, 1e-7);
			left = left || s.elbow_left;
			right = right || !s.elbow_left;
		}
		ASSERT_TRUE(found) << "pose " << n << ": the generating joints are not among the solutions";
		total += r.solutions.size();
		with_both_elbows += left && right;
	}
	// Both elbow configurations are found whenever the limits allow them: most random poses.
	EXPECT_GT(with_both_elbows, 3000u);
	EXPECT_GE(total, 10000u);
}

// At q5 = 0 or 180° (the wrist's singularity) only q4 ∓ q6 is defined; the flipped wrist is then
// solved afresh instead of being derived from the regular one, and every answer must still reach
// the pose, including just off the singularity where the derivation takes over.
TEST(ArmAnalyticIk, RoundTripAtAndNearTheWristSingularity)
{
	std::mt19937 rng(7);
	const RtxKinematics kin;
	const AnalyticIk ik;
	int solved = 0;
	for (int n = 0; n < 600; ++n)
	{
		RtxJoints j = test::randomReachableJoints(rng);
		const double offsets[] = {0.0, 1e-13, -1e-13, 1e-7};
		j.q_rad[4] = (n % 2 ? M_PI : 0.0) + offsets[n % 4];
		const Eigen::Isometry3d T = kin.T06(j);
		const IkResult r = ik.solve(T);
		solved += !r.solutions.empty();
		for (const auto& s : r.solutions)
		{
			const Eigen::Isometry3d Ts = kin.T06(s.joints);
			ASSERT_LT(test::positionError(Ts, T), 1e-6) << "pose " << n;
			ASSERT_LT(test::rotationError(Ts, T), 1e-9) << "pose " << n;
		}
	}
	EXPECT_GT(solved, 300);  // most of them are within the wrist motors' limits
}

TEST(ArmAnalyticIk, ReturnsBothElbowConfigurations)
{
	// Wrist 131.5 mm out along x (θ = 75°), gripper level along x: q2 = ±75°, q3 = ∓150°, q4 =
	// ±75°.
	const GripperPose g{{508 * std::cos(mrpt::DEG2RAD(75.0)) + 177, 0, 500}, 0, 0, 0};
	const auto sols = AnalyticIk().solveAll(poseFromGripper(g));
	ASSERT_EQ(sols.size(), 2u);
	EXPECT_NE(sols[0].elbow_left, sols[1].elbow_left);
	for (const auto& s : sols) EXPECT_NEAR(std::abs(mrpt::RAD2DEG(s.joints.q(3))), 150, 1e-9);
}

TEST(ArmAnalyticIk, ReturnsBothWristsAndEveryTurnWithinWideLimits)
{
	// With the yaw and wrist motors allowed a full turn each way, every elbow × wrist branch and
	// the ±360° turns within the limits are returned, and every one reproduces the pose.
	RtxOptions o;
	o.limits[static_cast<int>(Motor::Yaw)] = {-3600, 3600};
	o.limits[static_cast<int>(Motor::Wrist1)] = {-9000, 9000};
	o.limits[static_cast<int>(Motor::Wrist2)] = {-9000, 9000};
	const GripperPose g{{320, 0, 500}, 0, 20, 10};  // wrist ≈ 154 mm out: θ ≈ 72°
	const Eigen::Isometry3d T = poseFromGripper(g);
	const auto sols = AnalyticIk(o).solveAll(T);
	int left = 0, flipped = 0;
	for (const auto& s : sols)
	{
		left += s.elbow_left;
		flipped += s.wrist_flipped;
		EXPECT_LT(test::positionError(RtxKinematics(o).T06(s.joints), T), 1e-6);
		EXPECT_LT(test::rotationError(RtxKinematics(o).T06(s.joints), T), 1e-9);
	}
	EXPECT_GT(sols.size(), 4u);
	EXPECT_GT(left, 0);
	EXPECT_LT(left, static_cast<int>(sols.size()));
	EXPECT_GT(flipped, 0);
	EXPECT_LT(flipped, static_cast<int>(sols.size()));
}

TEST(ArmAnalyticIk, WristRadiusBeyondLimitIsNamed)
{
	const GripperPose g{{510 + 177, 0, 500}, 0, 0, 0};
	const IkResult r = AnalyticIk().solve(poseFromGripper(g));
	EXPECT_TRUE(r.solutions.empty());
	EXPECT_THAT(r.reason(), HasSubstr("wrist radius 510"));
	EXPECT_THAT(r.reason(), HasSubstr("507"));
	EXPECT_THROW(AnalyticIk().solveAll(poseFromGripper(g)), UnreachableError);
}

TEST(ArmAnalyticIk, ColumnRangeIsNamed)
{
	const GripperPose high{{400, 0, 1000}, 0, 0, 0}, low{{400, 0, -100}, 0, 0, 0};
	EXPECT_THAT(AnalyticIk().solve(poseFromGripper(high)).reason(), HasSubstr("column height"));
	EXPECT_THAT(AnalyticIk().solve(poseFromGripper(low)).reason(), HasSubstr("column height"));
}

TEST(ArmAnalyticIk, ShoulderLimitIsNamedForATargetBehindTheArm)
{
	// Wrist straight behind the column at full stretch: q2 = 180° beyond the ±90° shoulder.
	const GripperPose g{{-500 - 177, 0, 500}, 180, 0, 0};
	const IkResult r = AnalyticIk().solve(poseFromGripper(g));
	EXPECT_TRUE(r.solutions.empty());
	EXPECT_THAT(r.reason(), HasSubstr("shoulder count"));
}

TEST(ArmAnalyticIk, WristYawAndWristMotorLimitsAreNamed)
{
	// Wrist 400 mm out along x, gripper heading back at the column: the normal wrist needs a yaw of
	// ±142° (beyond ±110°), the flipped wrist a wrist-motor turn beyond ±180°.
	const GripperPose g{{400 - 177, 0, 500}, 180, 0, 0};
	const IkResult r = AnalyticIk().solve(poseFromGripper(g));
	EXPECT_TRUE(r.solutions.empty());
	EXPECT_THAT(r.reason(), HasSubstr("elbow left, wrist normal: yaw count -1382.52 outside limit "
	                                  "[-1071, 1071]"));
	EXPECT_THAT(r.reason(), HasSubstr("wrist flipped: wrist"));
}

TEST(ArmAnalyticIk, NonFinitePoseIsRejected)
{
	Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
	T.translation().x() = std::nan("");
	EXPECT_THAT(AnalyticIk().solve(T).reason(), HasSubstr("non-finite"));
}
