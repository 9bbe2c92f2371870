// The mrolr-head app class: argument errors, and each command's output against the library.
#include <mrolr/apps/HeadApp.h>
#include <mrolr/geometry/IdealHead.h>
#include <mrolr/util/Cli.h>
#include <mrolr/util/Config.h>

#include <nlohmann/json.hpp>

#include <gtest/gtest.h>

#include <iomanip>
#include <sstream>

using mrolr::apps::HeadApp;
using mrolr::util::UsageError;
namespace geo = mrolr::geometry;

namespace
{
// Runs the app as the shell would (negative numbers protected); returns stdout.
std::string runApp(std::vector<std::string> args, HeadApp* app_out = nullptr)
{
	args.insert(args.begin(), "mrolr-head");
	std::vector<const char*> argv;
	for (const auto& a : args) argv.push_back(a.c_str());
	HeadApp app;
	app.initialize(
	    mrolr::util::argsWithNegativeNumbersProtected(static_cast<int>(argv.size()), argv.data()));
	std::ostringstream out;
	EXPECT_EQ(app.run(out), mrolr::util::kExitOk);
	if (app_out) *app_out = app;
	return out.str();
}

std::vector<double> numbersIn(const std::string& line)
{
	std::istringstream in(line);
	std::vector<double> v;
	for (double x; in >> x;) v.push_back(x);
	return v;
}

const geo::BiSightHead& shippedHead()
{
	static const geo::BiSightHead head(geo::BiSightOptions::fromFile(HeadApp::defaultConfigPath()));
	return head;
}
}  // namespace

TEST(HeadApp, BadArgumentsAreUsageErrors)
{
	EXPECT_THROW(runApp({}), UsageError);  // no command
	EXPECT_THROW(runApp({"spin", "1", "2", "3"}), UsageError);
	EXPECT_THROW(runApp({"fixate", "1", "2"}), UsageError);
	EXPECT_THROW(runApp({"fixate", "1", "2", "3", "4"}), UsageError);
	EXPECT_THROW(runApp({"fixate", "1", "two", "3"}), UsageError);
	EXPECT_THROW(runApp({"--sigma-px", "-1", "measure", "1", "2", "3"}), UsageError);
	EXPECT_THROW(runApp({"--bogus", "measure", "1", "2", "3"}), UsageError);
	try
	{
		runApp({"project", "1", "2", "3"});
		FAIL();
	}
	catch (const UsageError& e)
	{
		EXPECT_NE(std::string(e.what()).find("X Y Z PAN TILT VL VR"), std::string::npos)
		    << e.what();
	}
}

TEST(HeadApp, FixateThenProjectGivesThePrincipalPoint)
{
	const std::vector<double> a = numbersIn(runApp({"fixate", "0.5", "-0.2", "2"}));
	ASSERT_EQ(a.size(), 4u);
	EXPECT_EQ(a[3], -a[2]);
	// Feed the printed angles back: 15 significant digits keep the fixation to well under 1e-6 px.
	std::vector<std::string> args = {"project", "0.5", "-0.2", "2"};
	for (double x : a)
	{
		std::ostringstream s;
		s << std::setprecision(15) << x;
		args.push_back(s.str());
	}
	const std::vector<double> px = numbersIn(runApp(args));
	const geo::BiSightOptions& o = shippedHead().options();
	ASSERT_EQ(px.size(), 4u);
	EXPECT_NEAR(px[0], o.u0_px, 1e-6);
	EXPECT_NEAR(px[1], o.v0_px, 1e-6);
	EXPECT_NEAR(px[2], o.u0_px, 1e-6);
	EXPECT_NEAR(px[3], o.v0_px, 1e-6);
}

TEST(HeadApp, ProjectAcceptsNegativeNumbersAndMatchesTheLibrary)
{
	HeadApp app;
	runApp({"project", "0.5", "-0.2", "2", "-0.1", "0", "0.05", "-0.05"}, &app);
	const Eigen::Vector4d px =
	    shippedHead().project({0.5, -0.2, 2}, {-0.1, 0, 0.05, -0.05}).asVector();
	ASSERT_EQ(app.output_values.size(), 4u);
	for (int i = 0; i < 4; ++i) EXPECT_EQ(app.output_values[i], px[i]);
	EXPECT_EQ(app.output_names, (std::vector<std::string>{"uL", "vL", "uR", "vR"}));
}

TEST(HeadApp, TriangulateJsonHasThePointAndCovariance)
{
	const geo::HeadAngles a{0.1, -0.05, -0.04, 0.06};
	const Eigen::Vector4d px = shippedHead().project({0.4, -0.3, 2.2}, a).asVector();
	std::vector<std::string> args = {"--json", "--sigma-px", "0.5", "triangulate"};
	for (double x : {px[0], px[1], px[2], px[3], a.pan, a.tilt, a.verg_left, a.verg_right})
	{
		std::ostringstream s;
		s << std::setprecision(17) << x;
		args.push_back(s.str());
	}
	const nlohmann::json j = nlohmann::json::parse(runApp(args));
	EXPECT_NEAR(j.at("X").get<double>(), 0.4, 1e-9);
	EXPECT_NEAR(j.at("Y").get<double>(), -0.3, 1e-9);
	EXPECT_NEAR(j.at("Z").get<double>(), 2.2, 1e-9);
	const Eigen::Matrix3d cov =
	    shippedHead().triangulate(geo::StereoPixels::fromVector(px), a, 0.5).cov;
	ASSERT_EQ(j.at("cov").size(), 3u);
	for (int r = 0; r < 3; ++r)
		for (int c = 0; c < 3; ++c)
			EXPECT_NEAR(j["cov"][r][c].get<double>(), cov(r, c), 1e-12 + 1e-9 * cov.norm());
}

TEST(HeadApp, MeasureIsTheIdealHead)
{
	const nlohmann::json j =
	    nlohmann::json::parse(runApp({"--json", "measure", "-0.5", "0.2", "3"}));
	const Eigen::Vector3d h = geo::idealHeadMeasure({-0.5, 0.2, 3}, 0.25);
	EXPECT_EQ(j.at("pan").get<double>(), h[0]);
	EXPECT_EQ(j.at("elevation").get<double>(), h[1]);
	EXPECT_EQ(j.at("vergence").get<double>(), h[2]);
	EXPECT_EQ(j.size(), 3u);
}

TEST(HeadApp, TextOutputHasAtLeast12SignificantDigits)
{
	const std::string line = runApp({"measure", "0.123456789", "0.2", "3"});
	const std::string first = line.substr(0, line.find(' '));
	EXPECT_GE(first.size(), 14u) << line;  // "0." + ≥ 12 digits
}

TEST(HeadApp, ConfigAndGeometryErrorsAreNotUsageErrors)
{
	EXPECT_THROW(runApp({"--config", "/nonexistent.ini", "measure", "1", "1", "1"}),
	             mrolr::util::ConfigError);
	EXPECT_THROW(runApp({"fixate", "0", "0", "-3"}), geo::FixationError);
}
