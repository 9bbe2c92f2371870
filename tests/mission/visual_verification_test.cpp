// Visual verification of the grasp (beyond thesis 7.2.2): from the pre-grasp pose the head fixates
// the object, recognises it again in a new stereo pair and corrects the grasp. A known error is
// injected into the first recognised pose ([retrieval] inject_pose_error_mm) and the grasp used is
// compared with the grasp at the object's true pose.
#include "MissionTestConfig.h"

#include <mrolr/mission/Mission.h>
#include <mrolr/util/Config.h>

#include <gtest/gtest.h>

#include <cmath>
#include <string>

using namespace mrolr;

namespace
{
constexpr double kInjected_mm = 25;

/** The short mission (start, table, home) with navigation from the ideal sensor: retrieval is
 * under test here. */
mission::test::Run runWith(double inject_mm, double max_correction_mm, bool verification)
{
	auto cfg = mission::test::defaultMissionConfig();
	cfg.write("navigation", "landmark_sensor", "ideal_sim");
	cfg.write("retrieval", "inject_pose_error_mm", std::to_string(inject_mm));
	cfg.write("retrieval", "max_grasp_correction_mm", std::to_string(max_correction_mm));
	cfg.write("retrieval", "visual_verification", verification ? "true" : "false");
	return mission::test::runMission(cfg, mission::test::shortRoute());
}

double number(const nlohmann::json& j, const char* key)
{
	return j.at(key).is_number() ? j.at(key).get<double>() : std::nan("");
}

bool anyReasonContains(const mission::RetrievalResult& g, const std::string& text)
{
	for (const auto& why : g.reasons)
		if (why.find(text) != std::string::npos) return true;
	return false;
}
}  // namespace

TEST(VisualVerification, InjectedPoseErrorIsCorrectedFromTheFixatedView)
{
	const auto run = runWith(kInjected_mm, 40, true);
	const auto& r = run.r;
	const auto& e = run.report["retrieval"];
	ASSERT_TRUE(r.found) << r.failure;
	const auto& g = r.retrieval;
	ASSERT_TRUE(g.attempted) << r.failure;
	EXPECT_NEAR(number(e, "object_error_before_mm"), kInjected_mm, 5.0);
	ASSERT_TRUE(g.verified) << "the fixated re-observation did not recognise the object";
	EXPECT_TRUE(g.correction_applied);
	EXPECT_FALSE(g.correction_refused);
	EXPECT_NEAR(g.correction_mm, kInjected_mm, 5.0);
	EXPECT_LT(number(e, "object_error_after_mm"), 4.0);
	EXPECT_LT(number(e, "grasp_error_mm"), 4.0)
	    << "the corrected grasp is not back near the true grasp";
	EXPECT_TRUE(r.retrieved);
	EXPECT_TRUE(run.report["eval"]["object_retrieved"].get<bool>());
}

TEST(VisualVerification, WithoutVerificationTheInjectedErrorReachesTheGrasp)
{
	const auto run = runWith(kInjected_mm, 40, false);
	const auto& r = run.r;
	ASSERT_TRUE(r.retrieval.attempted) << r.failure;
	EXPECT_FALSE(r.retrieval.verified);
	EXPECT_FALSE(r.retrieval.correction_applied);
	EXPECT_GT(number(run.report["retrieval"], "grasp_error_mm"), kInjected_mm - 5.0);
}

TEST(VisualVerification, CorrectionAboveTheBoundIsRefusedAndReported)
{
	const auto run = runWith(kInjected_mm, 10, true);
	const auto& r = run.r;
	const auto& g = r.retrieval;
	ASSERT_TRUE(g.verified) << r.failure;
	EXPECT_TRUE(g.correction_refused);
	EXPECT_FALSE(g.correction_applied);
	EXPECT_GT(g.correction_mm, 10.0);
	EXPECT_TRUE(anyReasonContains(g, "max_grasp_correction_mm")) << "no note of the refusal";
	EXPECT_GT(number(run.report["retrieval"], "grasp_error_mm"), kInjected_mm - 5.0)
	    << "the refused correction was applied";
}

TEST(VisualVerification, NegativeBoundIsAConfigErrorNamingTheKey)
{
	auto cfg = mission::test::defaultMissionConfig();
	cfg.write("retrieval", "max_grasp_correction_mm", "-1");
	try
	{
		mission::test::optionsFrom(cfg);
		FAIL() << "a negative max_grasp_correction_mm was accepted";
	}
	catch (const util::ConfigError& e)
	{
		EXPECT_NE(std::string(e.what()).find("max_grasp_correction_mm"), std::string::npos)
		    << e.what();
	}
}
