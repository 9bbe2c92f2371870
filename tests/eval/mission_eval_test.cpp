// eval's verdict on a robot's report: success only when the robot claimed it and the truth agrees;
// the object's rotation error modulo its symmetries; the truth read back from T.json as written;
// a malformed T.json names the field.
#include <mrolr/eval/MissionEval.h>
#include <mrolr/geometry/Frames.h>
#include <mrolr/geometry/PoseUnits.h>
#include <mrolr/mission/MissionOutputs.h>

#include "../common/ThrownMessage.h"

#include <gtest/gtest.h>

using namespace mrolr;
using nlohmann::json;

namespace
{
/** The smallest report eval reads: the robot claims success and holds the cube at home. */
json claimedSuccess()
{
	const json P = {{1e-4, 0, 0}, {0, 1e-4, 0}, {0, 0, 1e-4}};
	return {{"success", true},      {"failure", ""},        {"target", "alphabet_cube"},
	        {"found", false},       {"retrieved", true},    {"returned_home", true},
	        {"robot",
	         {{"success", true},
	          {"home", {{"name", "H"}, {"zxphi", {0.0, 0.0, 0.0}}}},
	          {"home_tolerance_m", 0.15},
	          {"head_height_m", 1.0},
	          {"final_estimate_zxphi", {0.01, 0.0, 0.0}},
	          {"final_odometry_zxphi", {0.3, 0.1, 0.0}},
	          {"path", json::array({{{"device_t_s", 0.0}, {"estimate", {0.0, 0.0, 0.0}}, {"P_vv", P}}})}}}};
}

eval::MissionTruth truthAt(double z, const std::string& held)
{
	eval::MissionTruth t;
	t.final_zxphi = {z, 0, 0};
	t.objects.push_back({"alphabet_cube", "alphabet_cube", Eigen::Isometry3d::Identity(),
	                     Eigen::Isometry3d::Identity()});
	t.objects.push_back({"cup", "cup", Eigen::Isometry3d::Identity(), Eigen::Isometry3d::Identity()});
	t.held = held;
	t.steps.push_back({0.0, {0, 0, 0}});
	return t;
}
}  // namespace

TEST(MissionEval, ARightClaimIsConfirmed)
{
	auto r = claimedSuccess();
	eval::evaluateMission(r, truthAt(0.02, "alphabet_cube"));
	EXPECT_TRUE(r["success"].get<bool>());
	EXPECT_TRUE(r["eval"]["confirms"].get<bool>());
	EXPECT_NEAR(r["final_position_error_m"].get<double>(), 0.02, 1e-12);
	EXPECT_NEAR(r["dead_reckoning_error_m"].get<double>(), std::hypot(0.28, 0.1), 1e-12);
	EXPECT_EQ(r["eval"]["nees"]["count"], 1);
}

TEST(MissionEval, TheRobotsClaimIsNotEnoughWhenTheTruthDisagrees)
{
	auto far = claimedSuccess();
	eval::evaluateMission(far, truthAt(0.4, "alphabet_cube"));  // it believes it is home
	EXPECT_FALSE(far["success"].get<bool>());
	EXPECT_FALSE(far["eval"]["agrees_home"].get<bool>());
	EXPECT_NE(far["failure"].get<std::string>().find("not home"), std::string::npos);
	auto wrong = claimedSuccess();
	eval::evaluateMission(wrong, truthAt(0.0, "cup"));  // it holds something, not the target
	EXPECT_FALSE(wrong["success"].get<bool>());
	EXPECT_FALSE(wrong["eval"]["object_held"].get<bool>());
	EXPECT_EQ(wrong["eval"]["held_instance"], "cup");
	auto hit = claimedSuccess();
	auto t = truthAt(0.0, "alphabet_cube");
	t.contact = eval::ContactTruth{"obstacle.crate", {1.0, 2.0}};
	eval::evaluateMission(hit, t);
	EXPECT_FALSE(hit["success"].get<bool>());
	EXPECT_EQ(hit["eval"]["collision"]["what"], "obstacle.crate");
	auto cup_aboard = claimedSuccess();
	auto u = truthAt(0.0, "");
	u.on_board = {"cup"};  // something rode home on the deck, not the target
	eval::evaluateMission(cup_aboard, u);
	EXPECT_FALSE(cup_aboard["success"].get<bool>());
	EXPECT_FALSE(cup_aboard["eval"]["object_retrieved"].get<bool>());
}

TEST(MissionEval, TheTargetOnTheDeckIsRetrieved)
{
	auto r = claimedSuccess();
	auto t = truthAt(0.02, "");
	t.on_board = {"alphabet_cube"};
	eval::evaluateMission(r, t);
	EXPECT_TRUE(r["success"].get<bool>());
	EXPECT_FALSE(r["eval"]["object_held"].get<bool>());
	EXPECT_TRUE(r["eval"]["object_on_board"].get<bool>());
	EXPECT_EQ(r["eval"]["on_board_instance"], "alphabet_cube");
	const auto back = eval::truthFromJson(eval::truthJson(t), "T.json");
	EXPECT_EQ(back.on_board, t.on_board);
}

TEST(MissionEval, TJsonReadsBackAndAMalformedOneNamesTheField)
{
	auto t = truthAt(1.25, "alphabet_cube");
	t.contact = eval::ContactTruth{"wall", {2.0, -1.0}};
	const auto back = eval::truthFromJson(eval::truthJson(t), "T.json");
	EXPECT_NEAR(back.final_zxphi.x(), 1.25, 1e-12);
	EXPECT_EQ(back.held, "alphabet_cube");
	ASSERT_EQ(back.objects.size(), 2u);
	EXPECT_EQ(back.objects[1].model, "cup");
	ASSERT_TRUE(back.contact.has_value());
	EXPECT_EQ(back.contact->what, "wall");
	json bad = eval::truthJson(t);
	bad["vehicle"].erase("x_m");
	const std::string message = test_support::messageOf<std::runtime_error>(
	    [&] { eval::truthFromJson(bad, "T.json"); }, "accepted");
	EXPECT_NE(message.find("T.json: missing field 'x_m'"), std::string::npos) << message;
}

namespace
{
/** The object's rotation error in a report that found it turned by @p turn_deg about its own z,
 * when its shape has the turns @p symmetry_deg. */
double rotationErrorFor(double turn_deg, const std::vector<double>& symmetry_deg)
{
	Eigen::Isometry3d T_OinW = Eigen::Isometry3d::Identity();  // W: y up; O: z up
	T_OinW.translation() = Eigen::Vector3d(0.1, 0.8, 1.5);
	T_OinW.linear() = (Eigen::AngleAxisd(0.5, Eigen::Vector3d::UnitY()) *
	                   Eigen::AngleAxisd(-M_PI / 2, Eigen::Vector3d::UnitX()))
	                      .toRotationMatrix();
	const Eigen::Isometry3d T_C0inW = geometry::T_C0inW(Eigen::Vector3d::Zero(), 1.0);
	const Eigen::Isometry3d T_OinC0 =
	    geometry::inMm(T_C0inW).inverse() * geometry::inMm(T_OinW) *
	    Eigen::AngleAxisd(turn_deg * M_PI / 180, Eigen::Vector3d::UnitZ());
	auto r = claimedSuccess();
	r["found"] = true;
	r["target"] = "can";
	r["robot"]["recognition"] = {{"frame", nullptr},
	                             {"search_estimate_zxphi", {0.0, 0.0, 0.0}},
	                             {"T_OinC0_mm", mission::matrix34(T_OinC0)}};
	auto t = truthAt(0.0, "");
	t.objects.push_back({"can_1", "can", T_OinW, T_OinW, symmetry_deg});
	eval::evaluateMission(r, eval::truthFromJson(eval::truthJson(t), "T.json"));
	EXPECT_EQ(r["found_instance"], "can_1");
	EXPECT_NEAR(r["object_translation_error_mm"].get<double>(), 0, 1e-9);
	EXPECT_EQ(r["eval"]["object_symmetry_deg"].get<std::vector<double>>(), symmetry_deg);
	return r["object_rotation_error_deg"].get<double>();
}
}  // namespace

TEST(MissionEval, AnObjectsRotationErrorIsTakenModuloTheTurnsThatMapItOntoItself)
{
	EXPECT_NEAR(rotationErrorFor(70, {-1}), 0, 1e-6);  // a body of revolution: any turn
	EXPECT_NEAR(rotationErrorFor(70, {0}), 70, 1e-6);
	EXPECT_NEAR(rotationErrorFor(180, {0, 180}), 0, 1e-6);
	EXPECT_NEAR(rotationErrorFor(170, {0, 180}), 10, 1e-6);
	json bad = eval::truthJson(truthAt(0.0, ""));
	bad["objects"][0]["symmetry_deg"] = "none";
	EXPECT_NE(test_support::messageOf<std::runtime_error>(
	              [&] { eval::truthFromJson(bad, "T.json"); })
	              .find("T.json: field 'symmetry_deg' is not a list of angles"),
	          std::string::npos);
}
