#include <mrolr/apps/CalibApp.h>
#include <mrolr/stereo/StereoCalibration.h>
#include <mrolr/util/Cli.h>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <sstream>

using mrolr::apps::CalibApp;

namespace
{
std::vector<std::string> args(const std::string& board, const std::string& out)
{
	const std::string d = "/usr/share/mrpt/datasets/stereo-calib/";
	return {"mrolr-calib", "--left", d + "*_left.jpg", "--right", d + "*_right.jpg",
	        "--board",     board,    "--square-mm",    "34",      "--out",
	        out,           "--json"};
}
}  // namespace

TEST(CalibApp, JsonReportsTheCalibrationWrittenToTheIni)
{
	const std::string out = ::testing::TempDir() + "calib_app.ini";
	CalibApp app;
	app.initialize(args("9x6", out));
	std::ostringstream ss;
	EXPECT_EQ(app.run(ss), 0);
	const auto j = nlohmann::json::parse(ss.str());
	for (const char* k : {"rms_px", "pairs_used", "baseline_mm", "fx_px", "fy_px"})
		EXPECT_TRUE(j.contains(k)) << k;
	EXPECT_LT(j["rms_px"].get<double>(), 0.5);
	EXPECT_EQ(j["pairs_used"].get<int>(), 4);
	const auto c = mrolr::stereo::loadStereoCalibration(out);
	EXPECT_DOUBLE_EQ(c.baseline_mm(), j["baseline_mm"].get<double>());
	EXPECT_DOUBLE_EQ(c.K_left(0, 0), j["fx_px"].get<double>());
}

TEST(CalibApp, BadArgumentsAreUsageErrors)
{
	CalibApp a;
	EXPECT_THROW(a.initialize({"mrolr-calib", "--left", "x"}), mrolr::util::UsageError);
	CalibApp b;
	auto bad = args("9x6", "/tmp/x.ini");
	bad[8] = "abc";  // --square-mm
	EXPECT_THROW(b.initialize(bad), mrolr::util::UsageError);
	CalibApp c;
	bad = args("9x6", "/tmp/x.ini");
	bad[2] = "/nonexistent/*_left.jpg";
	EXPECT_THROW(c.initialize(bad), mrolr::util::UsageError);
	CalibApp d;
	d.initialize(args("nine-by-six", "/tmp/x.ini"));
	std::ostringstream ss;
	EXPECT_THROW(d.run(ss), mrolr::util::UsageError);
}
