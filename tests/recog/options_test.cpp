#include <mrolr/recog/RecognitionOptions.h>
#include <mrolr/util/Config.h>

#include <mrpt/config/CConfigFile.h>
#include <mrpt/config/CConfigFileMemory.h>

#include "../common/ThrownMessage.h"

#include <gtest/gtest.h>

#include <sstream>

using namespace mrolr::recog;

// The shipped file holds the built-in defaults exactly.
TEST(RecogOptions, ShippedFileEqualsDefaults)
{
	mrpt::config::CConfigFile cfg(std::string(MROLR_SOURCE_DIR) + "/config/recognition.ini");
	RecognitionOptions o;
	o.loadFromConfigFile(cfg, "recognition");
	std::ostringstream a, b;
	o.dump(a);
	RecognitionOptions::defaults().dump(b);
	EXPECT_EQ(a.str(), b.str());
	EXPECT_EQ(o.levels.size(), 12u);
}

// dump() output read back gives the same options.
TEST(RecogOptions, DumpRoundTrips)
{
	auto o = RecognitionOptions::defaults();
	o.levels[3].rotation_deg = 2.75;
	o.pose_method = PoseMethod::Both;
	std::ostringstream s;
	s << "[recognition]\n";
	o.dump(s);
	mrpt::config::CConfigFileMemory cfg(s.str());
	RecognitionOptions r;
	r.loadFromConfigFile(cfg, "recognition");
	std::ostringstream a, b;
	o.dump(a);
	r.dump(b);
	EXPECT_EQ(a.str(), b.str());
}

namespace
{
std::string errorFor(const std::string& from, const std::string& to)
{
	std::ostringstream s;
	s << "[recognition]\n";
	RecognitionOptions::defaults().dump(s);
	std::string text = s.str();
	const auto pos = text.find(from);
	EXPECT_NE(pos, std::string::npos) << from;
	text.replace(pos, from.size(), to);
	mrpt::config::CConfigFileMemory cfg(text);
	RecognitionOptions r;
	return mrolr::test_support::messageOf<mrolr::util::ConfigError>(
	    [&] { r.loadFromConfigFile(cfg, "recognition"); });
}
}  // namespace

// Bad values are reported with the section and key.
TEST(RecogOptions, BadValuesNameTheKey)
{
	EXPECT_NE(errorFor("pose_method = faugeras_hebert", "pose_method = magic").find("pose_method"),
	          std::string::npos);
	EXPECT_NE(errorFor("clique_size = 5 5", "clique_size = 5 x").find("[recognition] clique_size"),
	          std::string::npos);
	EXPECT_NE(errorFor("clique_size = 5 5", "clique_size = 5.5 5").find("clique_size"),
	          std::string::npos);
	EXPECT_NE(errorFor("rotation_deg = 1.5 2", "rotation_deg = 1.5").find("rotation_deg"),
	          std::string::npos);
	EXPECT_NE(errorFor("length_ratio = 0.7", "length_ratio = 1.7").find("length_ratio"),
	          std::string::npos);
	EXPECT_NE(errorFor("levels = 12", "levels = 0").find("levels"), std::string::npos);
	// an optional key (absent from the shipped file) is still checked when given
	EXPECT_NE(
	    errorFor("verify_rotation_deg = 3", "verify_rotation_deg = three").find("verify_rotation_deg"),
	    std::string::npos);
	EXPECT_NE(errorFor("pose_method = faugeras_hebert\n", "").find("pose_method"), std::string::npos);
}
