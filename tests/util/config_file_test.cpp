// A configuration file with base files (util/ConfigFile.h): the file's keys laid over its base's,
// errors naming the file that gave a key, loops and missing bases refused by name.
#include "../common/FreshTempDir.h"
#include "../common/ThrownMessage.h"

#include <mrolr/util/Config.h>
#include <mrolr/util/ConfigFile.h>

#include <gtest/gtest.h>

#include <fstream>

using namespace mrolr::util;

namespace
{
void write(const std::string& path, const std::string& text)
{
	std::ofstream(path) << text;
}

std::string errorOf(const std::string& path)
{
	return mrolr::test_support::messageOf<ConfigError>([&] { ConfigFile::load(path); });
}
}  // namespace

TEST(ConfigFile, AFileOverridesItsBaseKeyByKeyAndBasesChain)
{
	const auto dir = mrolr::test_support::freshTempDir("config_file_chain");
	write(dir + "/root.ini", "[a]\nx = 1\ny = 2\n[b]\nz = root\n");
	write(dir + "/mid.ini", "[base]\nfile = root.ini\n[a]\ny = 20\n[c]\nw = mid\n");
	write(dir + "/top.ini", "# comment\n[base]\nfile = ./mid.ini\n[b]\nz = top\n");
	const auto cfg = ConfigFile::load(dir + "/top.ini");
	EXPECT_EQ(readString(cfg, "a", "x"), "1");    // from the root
	EXPECT_EQ(readString(cfg, "a", "y"), "20");   // the middle overrides the root
	EXPECT_EQ(readString(cfg, "b", "z"), "top");  // the top overrides both
	EXPECT_EQ(readString(cfg, "c", "w"), "mid");
	EXPECT_FALSE(cfg.sectionExists("base"));  // the directive is not a section of the result
	ASSERT_EQ(cfg.chain().size(), 3u);
	// messages name the file whose value stands
	EXPECT_NE(describeKey(cfg, "a", "x").find("root.ini [a] x"), std::string::npos);
	EXPECT_NE(describeKey(cfg, "a", "y").find("mid.ini [a] y"), std::string::npos);
	EXPECT_NE(describeKey(cfg, "b", "z").find("top.ini [b] z"), std::string::npos);
	auto with_set = cfg;
	with_set.set("a", "x", "5", "--set");
	EXPECT_EQ(readString(with_set, "a", "x"), "5");
	EXPECT_EQ(describeKey(with_set, "a", "x"), "--set [a] x");
	// a file without a base is itself
	const auto root = openConfigFile(dir + "/root.ini");
	EXPECT_EQ(readString(root, "a", "y"), "2");
	EXPECT_EQ(root.chain().size(), 1u);
}

TEST(ConfigFile, LoopsAndMissingOrEmptyBasesAreNamed)
{
	const auto dir = mrolr::test_support::freshTempDir("config_file_errors");
	write(dir + "/a.ini", "[base]\nfile = b.ini\n");
	write(dir + "/b.ini", "[base]\nfile = a.ini\n");
	EXPECT_NE(errorOf(dir + "/a.ini").find("loop"), std::string::npos) << errorOf(dir + "/a.ini");
	write(dir + "/self.ini", "[base]\nfile = self.ini\n");
	EXPECT_NE(errorOf(dir + "/self.ini").find("loop"), std::string::npos);
	write(dir + "/lost.ini", "[base]\nfile = nowhere.ini\n");
	const auto lost = errorOf(dir + "/lost.ini");
	EXPECT_NE(lost.find("cannot open"), std::string::npos) << lost;
	EXPECT_NE(lost.find("nowhere.ini"), std::string::npos) << lost;
	EXPECT_NE(lost.find("lost.ini [base] file"), std::string::npos) << lost;  // who named it
	write(dir + "/empty.ini", "[base]\nfile =\n");
	EXPECT_NE(errorOf(dir + "/empty.ini").find("[base] file"), std::string::npos);
	EXPECT_NE(errorOf(dir + "/absent.ini").find("cannot open"), std::string::npos);
}
