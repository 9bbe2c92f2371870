// mrolr-arm's app class run in-process: the thesis's transforms, IK output, JSON layout and errors.
#include <mrolr/apps/ArmApp.h>
#include <mrolr/util/Cli.h>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <sstream>

using mrolr::apps::ArmApp;
using ::testing::HasSubstr;

namespace
{
struct Outcome
{
	int code = -1;
	nlohmann::json json;
	std::string text;
};

Outcome run(std::vector<std::string> args)
{
	args.insert(args.begin(), "mrolr-arm");
	std::vector<const char*> argv;
	for (const auto& a : args) argv.push_back(a.c_str());
	ArmApp app;
	std::ostringstream out;
	app.out = &out;
	app.initialize(
	    mrolr::util::argsWithNegativeNumbersProtected(static_cast<int>(argv.size()), argv.data()));
	Outcome r;
	r.code = app.run();
	r.text = out.str();
	if (app.json) r.json = nlohmann::json::parse(r.text);
	return r;
}

double at(const nlohmann::json& T, int r, int c)
{
	return T.at(r).at(c).get<double>();
}
}  // namespace

TEST(ArmApp, FkPrintsT06AndCounts)
{
	const Outcome r = run({"fk", "922", "0", "0", "0", "0", "90", "0", "--json"});
	EXPECT_EQ(r.code, 0);
	EXPECT_NEAR(at(r.json["T"], 0, 3), 685, 1e-9);
	EXPECT_NEAR(at(r.json["T"], 2, 3), 922, 1e-9);
	EXPECT_EQ(r.json["counts"], nlohmann::json({0, 0, 0, 0, 0, 0}));
	EXPECT_EQ(r.json["T"].size(), 4u);
}

TEST(ArmApp, IkListsEverySolutionThatFkReproduces)
{
	const Outcome r = run({"ik", "400", "-50", "500", "-10", "20", "5", "--json"});
	ASSERT_EQ(r.code, 0);
	ASSERT_GE(r.json["solutions"].size(), 2u);
	for (const auto& s : r.json["solutions"])
	{
		std::vector<std::string> fk = {"fk"};
		for (double v : s["joints"]) fk.push_back(std::to_string(v));
		fk.push_back("--json");
		const Outcome f = run(fk);
		EXPECT_NEAR(at(f.json["T"], 0, 3), 400, 1e-3);
		EXPECT_NEAR(at(f.json["T"], 1, 3), -50, 1e-3);
		EXPECT_NEAR(f.json["gripper"]["pitch_deg"].get<double>(), 20, 1e-4);
		EXPECT_EQ(s["counts"].size(), 6u);
	}
}

TEST(ArmApp, IkGivesTheReasonWhenUnreachable)
{
	const Outcome r = run({"ik", "800", "0", "500", "0", "0", "0", "--json"});
	EXPECT_EQ(r.code, mrolr::util::kExitFailure);
	EXPECT_TRUE(r.json["solutions"].empty());
	EXPECT_THAT(r.json["reason"].get<std::string>(), HasSubstr("wrist radius"));
	const Outcome t = run({"ik", "--pose", "1,0,0,0,0,1,0,0,0,0,1,2000"});
	EXPECT_THAT(t.text, HasSubstr("no solution: column height"));
}

TEST(ArmApp, GraspReproducesTheThesisParallelMounting)
{
	const Outcome r = run({"grasp", "--object-in-c0", "0,1,0,470,0,0,-1,-441,-1,0,0,847", "--grasp",
	                       "0,0,0,-111.1,0,0", "--mount", "parallel", "--json"});
	const nlohmann::json printed = {
	    {-1, 0, 0, 220}, {0, 1, 0, -570}, {0, 0, -1, 270}, {0, 0, 0, 1}};
	for (int i = 0; i < 4; ++i)
		for (int j = 0; j < 4; ++j) EXPECT_NEAR(at(r.json["T"], i, j), at(printed, i, j), 1e-12);
	// A horizontal approach towards the column reaches it (the wrist stays within 507 mm).
	EXPECT_EQ(r.code, 0);
	EXPECT_FALSE(r.json["solutions"].empty());
	EXPECT_NEAR(at(r.json["T_GinA"], 0, 3), 220, 1e-9);
}

TEST(ArmApp, CalibrateGivesTheFortyFiveDegreeMounting)
{
	const Outcome r =
	    run({"calibrate", "--object-in-arm", "-.707,0,.707,545,.707,0,.707,0,0,1,0,429",
	         "--object-in-c0", "1,0,0,747,0,1,0,-246,0,0,1,1003.3", "--json"});
	EXPECT_EQ(r.code, 0);
	EXPECT_NEAR(at(r.json["T_AinC0"], 0, 3), 1132.37, 0.01);
	EXPECT_NEAR(at(r.json["T_AinC0"], 1, 3), -675, 1e-9);
	EXPECT_NEAR(at(r.json["T_AinC0"], 2, 3), 617.93, 0.01);
	// And the mounting file "45" is that calibration.
	const Outcome g = run({"grasp", "--object-in-c0", "1,0,0,747,0,1,0,-246,0,0,1,1003.3",
	                       "--grasp", "0,0,0,0,0,0", "--mount", "45", "--json"});
	EXPECT_NEAR(at(g.json["T"], 0, 3), 545, 1e-3);
	EXPECT_NEAR(at(g.json["T"], 2, 3), 429, 1e-3);
}

TEST(ArmApp, BadArgumentsAreUsageErrors)
{
	using mrolr::util::UsageError;
	EXPECT_THROW(run({}), UsageError);
	EXPECT_THROW(run({"dance"}), UsageError);
	EXPECT_THROW(run({"fk", "1", "2"}), UsageError);
	EXPECT_THROW(run({"fk", "922", "0", "0", "x", "0", "90", "0"}), UsageError);
	EXPECT_THROW(run({"ik", "--pose", "1,2,3"}), UsageError);
	EXPECT_THROW(run({"ik", "1", "2", "3", "4", "5", "6", "--pose", "1,0,0,0,0,1,0,0,0,0,1,0"}),
	             UsageError);
	EXPECT_THROW(run({"grasp", "--object-in-c0", "2,0,0,0,0,1,0,0,0,0,1,0", "--grasp",
	                  "0,0,0,0,0,0", "--mount", "parallel"}),
	             UsageError);
	EXPECT_THROW(run({"grasp", "--object-in-c0", "1,0,0,0,0,1,0,0,0,0,1,0", "--grasp", "0,0,0",
	                  "--mount", "parallel"}),
	             UsageError);
	EXPECT_THROW(run({"grasp", "--object-in-c0", "1,0,0,0,0,1,0,0,0,0,1,0", "--grasp",
	                  "0,0,0,0,0,0", "--mount", "/nonexistent.ini"}),
	             std::runtime_error);
}

TEST(ArmApp, JacobianSolverIsOffered)
{
	const Outcome r = run({"ik", "400", "-50", "500", "-10", "20", "5", "--jacobian", "--json"});
	EXPECT_TRUE(r.json["jacobian"]["converged"].get<bool>());
	EXPECT_LT(r.json["jacobian"]["position_error_mm"].get<double>(), 1e-6);
}
