// The options binder (util/OptionsBinder.h): one declaration loads, checks and dumps a key, and
// what it dumps loads back to the same options.
#include <mrolr/util/OptionsBinder.h>

#include <mrpt/config/CConfigFileMemory.h>

#include "../common/ThrownMessage.h"

#include <gtest/gtest.h>

#include <sstream>

using namespace mrolr::util;

namespace
{
enum class Mode
{
	Fast,
	Exact
};

struct Demo
{
	double radius_mm = 5;
	int count = 3;
	bool stage = false;
	std::string name = "demo";
	Mode mode = Mode::Fast;
	std::vector<double> xyz_m{0, 0, 0};
	double optional_gain = 0.25;
};

const OptionsBinder<Demo>& binder()
{
	static const auto b = OptionsBinder<Demo>()
	                          .number("radius_mm", &Demo::radius_mm, 0, 100)
	                          .integer("count", &Demo::count, 1, 10)
	                          .flag("stage", &Demo::stage)
	                          .text("name", &Demo::name)
	                          .choice("mode", &Demo::mode,
	                                  ChoiceNames<Mode>{{"fast", Mode::Fast}, {"exact", Mode::Exact}})
	                          .numbers("xyz_m", &Demo::xyz_m, 3, -10, 10)
	                          .number("optional_gain", &Demo::optional_gain, 0, 1,
	                                  Presence::Optional);
	return b;
}

const std::string kGood =
    "[d]\nradius_mm = 12.5\ncount = 7\nstage = yes\nname = left arm\nmode = exact\n"
    "xyz_m = 1 -2 3.5\n";

std::string errorOf(const std::string& text)
{
	Demo d;
	return mrolr::test_support::messageOf<ConfigError>(
	    [&] { binder().load(mrpt::config::CConfigFileMemory(text), "d", d); });
}
}  // namespace

TEST(OptionsBinder, LoadsEveryDeclaredKeyAndKeepsTheDefaultOfAnAbsentOptionalOne)
{
	Demo d;
	binder().load(mrpt::config::CConfigFileMemory(kGood), "d", d);
	EXPECT_EQ(d.radius_mm, 12.5);
	EXPECT_EQ(d.count, 7);
	EXPECT_TRUE(d.stage);
	EXPECT_EQ(d.name, "left arm");
	EXPECT_EQ(d.mode, Mode::Exact);
	EXPECT_EQ(d.xyz_m, (std::vector<double>{1, -2, 3.5}));
	EXPECT_EQ(d.optional_gain, 0.25);
	binder().load(mrpt::config::CConfigFileMemory(kGood + "optional_gain = 0.5\n"), "d", d);
	EXPECT_EQ(d.optional_gain, 0.5);
}

TEST(OptionsBinder, WhatItDumpsLoadsBackToTheSameOptions)
{
	Demo a;
	binder().load(mrpt::config::CConfigFileMemory(kGood), "d", a);
	std::ostringstream out;
	binder().dump(out, a);
	EXPECT_EQ(out.str(),
	          "radius_mm = 12.5\ncount = 7\nstage = true\nname = left arm\nmode = exact\n"
	          "xyz_m = 1 -2 3.5\noptional_gain = 0.25\n");
	Demo b;
	b.mode = Mode::Fast, b.count = 1;
	binder().load(mrpt::config::CConfigFileMemory("[d]\n" + out.str()), "d", b);
	std::ostringstream again;
	binder().dump(again, b);
	EXPECT_EQ(again.str(), out.str());
	EXPECT_EQ(binder().keys().size(), 7u);
}

TEST(OptionsBinder, EveryBadValueIsNamedWithItsKey)
{
	struct Case
	{
		std::string from, to, key, why;
	};
	const std::vector<Case> cases = {
	    {"radius_mm = 12.5\n", "", "radius_mm", "missing"},
	    {"radius_mm = 12.5", "radius_mm = 150", "radius_mm", ""},
	    {"radius_mm = 12.5", "radius_mm = twelve", "radius_mm", ""},
	    {"count = 7", "count = 0", "count", ""},
	    {"count = 7", "count = 7.5", "count", ""},
	    {"stage = yes", "stage = perhaps", "stage", ""},
	    {"mode = exact", "mode = quick", "mode", "'quick' is not one of fast, exact"},
	    {"xyz_m = 1 -2 3.5", "xyz_m = 1 -2", "xyz_m", ""},
	    {"xyz_m = 1 -2 3.5", "xyz_m = 1 -2 30", "xyz_m", ""},
	    {"name = left arm\n", "name = left arm\noptional_gain = 2\n", "optional_gain", ""}};
	for (const auto& c : cases)
	{
		std::string text = kGood;
		text.replace(text.find(c.from), c.from.size(), c.to);
		const std::string e = errorOf(text);
		EXPECT_NE(e.find("[d] " + c.key), std::string::npos) << c.to << " -> " << e;
		EXPECT_NE(e.find(c.why), std::string::npos) << c.to << " -> " << e;
	}
	EXPECT_THROW(OptionsBinder<Demo>().flag("stage", &Demo::stage).flag("stage", &Demo::stage),
	             std::logic_error);
}

TEST(OptionsBinder, AKeyFixedInCodeIsRefusedNamingWhereItLives)
{
	struct Tuned
	{
		double gain = 2;
		double margin_mm = 7;  // fixed: not read
	};
	const auto b = OptionsBinder<Tuned>()
	                   .number("gain", &Tuned::gain, 0, 10)
	                   .fixed({"margin_mm", "retired_flag"}, "demo/Tuned.h");
	Tuned t;
	b.load(mrpt::config::CConfigFileMemory("[t]\ngain = 3\n"), "t", t);
	EXPECT_EQ(t.gain, 3);
	EXPECT_EQ(t.margin_mm, 7);
	for (const std::string key : {"margin_mm", "retired_flag"})
	{
		try
		{
			b.load(mrpt::config::CConfigFileMemory("[t]\ngain = 3\n" + key + " = 9\n"), "t", t);
			FAIL() << key << " was read";
		}
		catch (const ConfigError& e)
		{
			const std::string what = e.what();
			EXPECT_NE(what.find("[t] " + key), std::string::npos) << what;
			EXPECT_NE(what.find("demo/Tuned.h"), std::string::npos) << what;
		}
		EXPECT_EQ(t.margin_mm, 7);
	}
	std::ostringstream dumped;  // and it is not dumped: a dump loads back
	b.dump(dumped, t);
	EXPECT_EQ(dumped.str(), "gain = 3\n");
}
