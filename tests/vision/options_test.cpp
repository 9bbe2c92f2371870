// VisionOptions: the shipped config loads, dump round-trips, errors name file, section and key.
#include "TestScene.h"

#include <mrolr/util/Config.h>

#include <mrpt/config/CConfigFileMemory.h>

#include <gtest/gtest.h>

#include <sstream>

using namespace mrolr::vision;

TEST(VisionOptions, ShippedConfigHasTheThesisValues)
{
	const VisionOptions o = test::configuredVision();
	EXPECT_EQ(o.patch_size_px, 13);
	EXPECT_DOUBLE_EQ(o.nssd_threshold, 0.9);
	EXPECT_DOUBLE_EQ(o.search_n_sigma, 3);
	EXPECT_DOUBLE_EQ(o.epipolar_band_px, 7);
	EXPECT_DOUBLE_EQ(o.lockon_radius_px, 2);
	EXPECT_DOUBLE_EQ(o.nssd_ambiguity_margin, 0);  // optional key, off: the thesis's matching
}

TEST(VisionOptions, DumpRoundTrips)
{
	VisionOptions a;
	a.nssd_threshold = 0.7;
	a.nssd_ambiguity_margin = 0.1;
	a.fixation_max_attempts = 9;
	a.selection = Selection::Saccade;
	std::ostringstream s;
	s << "[v]\n";
	a.dump(s);
	mrpt::config::CConfigFileMemory cfg(s.str());
	VisionOptions b;
	b.loadFromConfigFile(cfg, "v");
	std::ostringstream t;
	b.dump(t);
	EXPECT_EQ(s.str(), "[v]\n" + t.str());
}

TEST(VisionOptions, ErrorsNameTheKey)
{
	std::ostringstream s;
	s << "[v]\n";
	VisionOptions().dump(s);
	std::string text = s.str();
	const auto at = text.find("patch_size_px = 13");
	mrpt::config::CConfigFileMemory even(text.substr(0, at) + "patch_size_px = 12" +
	                                     text.substr(at + 18));
	VisionOptions o;
	try
	{
		o.loadFromConfigFile(even, "v");
		FAIL() << "an even patch size was accepted";
	}
	catch (const mrolr::util::ConfigError& e)
	{
		EXPECT_NE(std::string(e.what()).find("patch_size_px"), std::string::npos) << e.what();
	}
	const auto sel = text.find("selection = largest_vs");
	mrpt::config::CConfigFileMemory badSelection(text.substr(0, sel) + "selection = random\n");
	try
	{
		o.loadFromConfigFile(badSelection, "v");
		FAIL() << "an unknown selection was accepted";
	}
	catch (const mrolr::util::ConfigError& e)
	{
		EXPECT_NE(std::string(e.what()).find("selection"), std::string::npos) << e.what();
	}
	mrpt::config::CConfigFileMemory missing("[v]\nnssd_threshold = 0.9\n");
	EXPECT_THROW(o.loadFromConfigFile(missing, "v"), mrolr::util::ConfigError);
	EXPECT_THROW(VisionOptions::fromFile("/nonexistent/slam.ini"), mrolr::util::ConfigError);
}
