// Motor encoder counts (compute_xyz scale factors and limits), the options file and pose text.
#include "ArmTestUtil.h"

#include <mrolr/arm/ArmError.h>
#include <mrolr/arm/JacobianIk.h>
#include <mrolr/arm/PoseText.h>
#include <mrolr/util/Config.h>

#include <mrpt/config/CConfigFile.h>
#include <mrpt/config/CConfigFileMemory.h>
#include <mrpt/core/bits_math.h>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <sstream>

using namespace mrolr::arm;
using ::testing::HasSubstr;

TEST(ArmCounts, ScaleFactorsOfComputeXyz)
{
	const RtxOptions o;
	RtxJoints j;
	j.d1_mm = 922 - 0.2667 * 1000;  // 1000 counts down the column
	j.q_rad = {0,
	           mrpt::DEG2RAD(0.03422 * 100),
	           mrpt::DEG2RAD(-0.06844 * 200),
	           mrpt::DEG2RAD(0.10267 * 300),
	           mrpt::DEG2RAD(90 - 0.07415 * 40),
	           mrpt::DEG2RAD(0.07415 * 10)};
	const MotorCounts c = jointsToCounts(j, o);
	const double expected[] = {-1000, 100, -200, 300, -40 + 10, -40 - 10};
	for (int i = 0; i < kMotorCount; ++i) EXPECT_NEAR(c[static_cast<size_t>(i)], expected[i], 1e-9);
	EXPECT_EQ(roundCounts(c)[0], -1000);
}

TEST(ArmCounts, RoundTripOnRandomJoints)
{
	std::mt19937 rng(5);
	const RtxOptions o;
	for (int n = 0; n < 1000; ++n)
	{
		const RtxJoints j = test::randomJoints(rng);
		const RtxJoints back = countsToJoints(jointsToCounts(j, o), o);
		EXPECT_LT((back.active() - j.active()).cwiseAbs().maxCoeff(), 1e-9);
	}
}

TEST(ArmCounts, LimitsOfComputeXyzAreNamed)
{
	const RtxOptions o;
	MotorCounts c{-10, 2631, 0, 0, 0, 0};
	EXPECT_THAT(limitViolation(c, o), HasSubstr("shoulder count 2631 outside limit [-2630, 2630]"));
	c = {-10, 0, 2207, 0, 0, 0};
	EXPECT_THAT(limitViolation(c, o), HasSubstr("elbow count 2207 outside limit [-2630, 2206]"));
	c = {-3555, 0, 0, 0, 0, 0};
	EXPECT_THAT(limitViolation(c, o), HasSubstr("column count -3555 outside limit [-3554, 0]"));
	c = {0, 0, -2630, 0, 0, 0};
	EXPECT_EQ(limitViolation(c, o), "");
	RtxJoints j;
	j.d1_mm = 1000;  // above the top of the column
	EXPECT_THROW(requireWithinLimits(j, o), UnreachableError);
}

TEST(ArmCounts, ConfigFileEqualsDefaultsAndDumpReadsBack)
{
	const RtxOptions file = RtxOptions::fromFile(MROLR_SOURCE_DIR "/config/arm_rtx.ini");
	std::ostringstream a, b;
	file.dump(a);
	RtxOptions().dump(b);
	EXPECT_EQ(a.str(), b.str());
	mrpt::config::CConfigFileMemory mem("[rtx]\n" + a.str());
	RtxOptions again;
	again.a2_mm = 1;
	again.loadFromConfigFile(mem, "rtx");
	std::ostringstream c;
	again.dump(c);
	EXPECT_EQ(c.str(), a.str());
	const auto [shipped, defaults] =
	    test::shippedAndDefaultDump<JacobianIkOptions>("rtx_jacobian_ik");
	EXPECT_EQ(shipped, defaults);
}

TEST(ArmCounts, BadConfigNamesSectionAndKey)
{
	std::ostringstream s;
	RtxOptions().dump(s);
	std::string text = "[rtx]\n" + s.str();
	text.replace(text.find("a3_mm = 254"), 11, "a3_mm = abc");
	mrpt::config::CConfigFileMemory mem(text);
	RtxOptions o;
	try
	{
		o.loadFromConfigFile(mem, "rtx");
		FAIL() << "malformed a3_mm accepted";
	}
	catch (const mrolr::util::ConfigError& e)
	{
		EXPECT_THAT(e.what(), HasSubstr("a3_mm"));
		EXPECT_THAT(e.what(), HasSubstr("rtx"));
	}
	EXPECT_THROW(RtxOptions::fromFile("/nonexistent/arm.ini"), mrolr::util::ConfigError);
}

TEST(ArmPoseText, TwelveNumbersRowByRow)
{
	const Eigen::Isometry3d T = parsePose12("0,0,1,-627, 1,0,0,-1040, 0,1,0,711", "--pose");
	EXPECT_DOUBLE_EQ(T.matrix()(0, 3), -627);
	EXPECT_DOUBLE_EQ(T.matrix()(1, 0), 1);
	EXPECT_DOUBLE_EQ(T.matrix()(2, 1), 1);
	const auto v = poseTo12(T);
	EXPECT_EQ(v.size(), 12u);
	EXPECT_DOUBLE_EQ(v[11], 711);
}

TEST(ArmPoseText, RejectsWhatIsNotARigidTransform)
{
	EXPECT_THAT([] { parsePose12("1,2,3", "--pose"); },
	            ::testing::ThrowsMessage<PoseInputError>(HasSubstr("--pose: expected 12 numbers")));
	EXPECT_THAT([] { parsePose12("2,0,0,0, 0,1,0,0, 0,0,1,0", "--object-in-c0"); },
	            ::testing::ThrowsMessage<PoseInputError>(
	                HasSubstr("--object-in-c0: the 3x3 part is not a rotation")));
	EXPECT_THAT([] { parsePose12("-1,0,0,0, 0,1,0,0, 0,0,1,0", "P"); },
	            ::testing::ThrowsMessage<PoseInputError>(HasSubstr("det = -1")));
	EXPECT_THAT([] { parsePose12("1,0,0,x, 0,1,0,0, 0,0,1,0", "P"); },
	            ::testing::ThrowsMessage<PoseInputError>(HasSubstr("'x' is not a number")));
	// The thesis's 0.707 for 1/√2 is accepted and made exactly orthonormal.
	const Eigen::Isometry3d T = parsePose12("-.707,0,.707,545, .707,0,.707,0, 0,1,0,429", "P");
	EXPECT_LT((T.linear().transpose() * T.linear() - Eigen::Matrix3d::Identity()).norm(), 1e-12);
}
