#include <mrolr/util/Cli.h>
#include <mrolr/util/Config.h>

#include "../common/ThrownMessage.h"

#include <gtest/gtest.h>
#include <mrpt/config/CConfigFile.h>
#include <mrpt/config/CConfigFileMemory.h>

#include <cstdio>
#include <fstream>

using mrolr::util::ConfigError;

namespace
{
mrpt::config::CConfigFileMemory makeCfg()
{
	return mrpt::config::CConfigFileMemory(
		"[s]\n"
		"good = 1.5\n"
		"bad = 1.5abc\n"
		"n = 42\n"
		"list = 1, 2 3\n"
		"flag = Yes\n");
}

std::string errorOf(const std::function<void()>& f)
{
	return mrolr::test_support::messageOf<ConfigError>(f);
}
}  // namespace

TEST(Config, ReadsWellFormedValues)
{
	const auto cfg = makeCfg();
	EXPECT_DOUBLE_EQ(mrolr::util::readDouble(cfg, "s", "good"), 1.5);
	EXPECT_EQ(mrolr::util::readInt(cfg, "s", "n"), 42);
	EXPECT_EQ(mrolr::util::readDoubles(cfg, "s", "list", 3), (std::vector<double>{1, 2, 3}));
	EXPECT_TRUE(mrolr::util::readBool(cfg, "s", "flag", false));
	EXPECT_DOUBLE_EQ(mrolr::util::readDouble(cfg, "s", "absent", 7.0), 7.0);
}

TEST(Config, MalformedValueNamesSectionKeyAndValue)
{
	const auto cfg = makeCfg();
	const std::string msg = errorOf([&] { mrolr::util::readDouble(cfg, "s", "bad"); });
	EXPECT_NE(msg.find("[s] bad"), std::string::npos) << msg;
	EXPECT_NE(msg.find("1.5abc"), std::string::npos) << msg;
	// A fallback does not hide a malformed value.
	EXPECT_FALSE(errorOf([&] { mrolr::util::readDouble(cfg, "s", "bad", 0.0); }).empty());
	EXPECT_FALSE(errorOf([&] { mrolr::util::readDoubles(cfg, "s", "list", 2); }).empty());
	EXPECT_FALSE(errorOf([&] { mrolr::util::readInt(cfg, "s", "good"); }).empty());
}

TEST(Config, MissingKeyNamesFileSectionAndKey)
{
	const std::string path = ::testing::TempDir() + "mrolr_config_test.ini";
	{
		std::ofstream f(path);
		f << "[sec]\nx = 1\n";
	}
	mrpt::config::CConfigFile cfg(path);
	const std::string msg = errorOf([&] { mrolr::util::readDouble(cfg, "sec", "y_m"); });
	EXPECT_NE(msg.find(path), std::string::npos) << msg;
	EXPECT_NE(msg.find("[sec] y_m"), std::string::npos) << msg;
	EXPECT_NE(msg.find("missing"), std::string::npos) << msg;
	std::remove(path.c_str());
}

TEST(Config, RangeCheckNamesKey)
{
	const auto cfg = makeCfg();
	EXPECT_NO_THROW(mrolr::util::requireInRange(cfg, "s", "good", 1.5, 0, 2));
	const std::string msg =
		errorOf([&] { mrolr::util::requireInRange(cfg, "s", "good", 1.5, 2, 3); });
	EXPECT_NE(msg.find("[s] good"), std::string::npos) << msg;
}

TEST(Cli, NegativeNumbersSurviveAndParse)
{
	const char* argv[] = {"prog", "project", "-0.2", "--json", "-3e-4", "-x"};
	const auto args = mrolr::util::argsWithNegativeNumbersProtected(6, argv);
	EXPECT_EQ(args[2], " -0.2");
	EXPECT_EQ(args[3], "--json");
	EXPECT_EQ(args[5], "-x");
	EXPECT_DOUBLE_EQ(mrolr::util::parseNumberArg(args[4], "Z"), -3e-4);
	EXPECT_THROW(mrolr::util::parseNumberArg("1.2.3", "Z"), mrolr::util::UsageError);
	EXPECT_EQ(mrolr::util::parseNumberList("1,-2,3", 3, "pose").at(1), -2.0);
	EXPECT_THROW(mrolr::util::parseNumberList("1,2", 3, "pose"), mrolr::util::UsageError);
}

TEST(Cli, ProjectFileFallsBackToTheSourceTree)
{
	// A shipped file is found whatever the working directory.
	const std::string found = mrolr::util::projectFile("config/bisight.ini");
	EXPECT_TRUE(std::ifstream(found).good()) << found;
	EXPECT_EQ(mrolr::util::projectFile("no/such/file.ini"), "no/such/file.ini");
	EXPECT_THROW(mrolr::util::requireProjectFile("no/such/file.ini"), std::runtime_error);
	EXPECT_EQ(mrolr::util::requireProjectFile(found), found);
}
