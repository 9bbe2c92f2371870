// config/bisight.ini and the strict reading of [bisight].
#include <mrolr/geometry/BiSightOptions.h>
#include <mrolr/util/Config.h>

#include <mrpt/config/CConfigFileMemory.h>

#include "../common/ThrownMessage.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <sstream>

using namespace mrolr::geometry;
using mrolr::util::ConfigError;

namespace
{
std::string dumped(const BiSightOptions& o)
{
	std::ostringstream s;
	o.dump(s);
	return s.str();
}

// The [bisight] section of the defaults with one key's line replaced (or removed if empty).
std::string sectionWith(const std::string& key, const std::string& line)
{
	std::istringstream in(dumped(BiSightOptions()));
	std::string out = "[bisight]\n", l;
	while (std::getline(in, l)) out += (l.rfind(key + " ", 0) == 0 ? line : l) + "\n";
	return out;
}

std::string errorOf(const std::string& text)
{
	BiSightOptions o;
	return mrolr::test_support::messageOf<ConfigError>(
	    [&] { o.loadFromConfigFile(mrpt::config::CConfigFileMemory(text), "bisight"); },
	    "no error");
}
}  // namespace

TEST(BiSightOptions, ShippedConfigHasTheThesisValues)
{
	const BiSightOptions o = BiSightOptions::fromFile(MROLR_SOURCE_DIR "/config/bisight.ini");
	EXPECT_EQ(o.interocular_m, 0.25);  // thesis 5.3.1
	EXPECT_EQ(o.focal_px_v, 807);      // thesis 5.3.1
	EXPECT_EQ(o.image_width_px, 640);
	EXPECT_EQ(o.image_height_px, 480);
	// The struct's defaults are the shipped file, key for key.
	EXPECT_EQ(dumped(o), dumped(BiSightOptions()));
}

TEST(BiSightOptions, DumpReadsBack)
{
	BiSightOptions o;
	o.interocular_m = 0.3;
	o.u0_px = 301.125;
	o.vergence_limit_deg = 33;
	BiSightOptions back;
	back.loadFromConfigFile(mrpt::config::CConfigFileMemory("[bisight]\n" + dumped(o)), "bisight");
	EXPECT_EQ(dumped(back), dumped(o));
}

TEST(BiSightOptions, ErrorsNameFileSectionAndKey)
{
	EXPECT_EQ(errorOf(sectionWith("none", "")), "no error");
	EXPECT_NE(errorOf(sectionWith("focal_px_v", "")).find("[bisight] focal_px_v"),
	          std::string::npos);
	const std::string bad = errorOf(sectionWith("tilt_offset_m", "tilt_offset_m = 5cm"));
	EXPECT_NE(bad.find("[bisight] tilt_offset_m"), std::string::npos) << bad;
	EXPECT_NE(bad.find("5cm"), std::string::npos) << bad;
	EXPECT_NE(errorOf(sectionWith("focal_px_u", "focal_px_u = -807")).find("focal_px_u"),
	          std::string::npos);
	EXPECT_NE(
	    errorOf(sectionWith("image_width_px", "image_width_px = 640.5")).find("image_width_px"),
	    std::string::npos);
	EXPECT_NE(errorOf(sectionWith("pan_limit_deg", "pan_limit_deg = 270")).find("pan_limit_deg"),
	          std::string::npos);
	EXPECT_NE(errorOf(sectionWith("interocular_m", "interocular_m = 0")).find("interocular_m"),
	          std::string::npos);
}

TEST(BiSightOptions, FileErrorsNameTheFile)
{
	const std::string path = ::testing::TempDir() + "bisight_missing_key.ini";
	std::ofstream(path) << sectionWith("v0_px", "");
	try
	{
		BiSightOptions::fromFile(path);
		FAIL() << "expected ConfigError";
	}
	catch (const ConfigError& e)
	{
		EXPECT_NE(std::string(e.what()).find(path + " [bisight] v0_px"), std::string::npos)
		    << e.what();
	}
	std::remove(path.c_str());
	EXPECT_THROW(BiSightOptions::fromFile("/nonexistent/bisight.ini"), ConfigError);
	EXPECT_THROW(BiSightOptions::fromFile(MROLR_SOURCE_DIR "/config/bisight.ini", "nosuch"),
	             ConfigError);
}
