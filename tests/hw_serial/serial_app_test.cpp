// mrolr-serial: arguments, one-shot requests to an emulated device, and the emulators' run.
#include "FakeDevices.h"

#include <mrolr/apps/SerialApp.h>
#include <mrolr/util/Cli.h>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>

using namespace mrolr;

namespace
{
apps::SerialApp parsed(std::vector<std::string> args)
{
	args.insert(args.begin(), "mrolr-serial");
	apps::SerialApp app;
	app.initialize(args);
	return app;
}
}  // namespace

TEST(SerialApp, SendPrintsTheReplyOfAnEmulatedDevice)
{
	fake::Base base;
	hw_serial::BaseHandler handler(base);
	hw_serial::PtyEmulator pty(handler);
	auto step = parsed({"send", pty.slavePath(), "STEP", "0.25", " -0.5", "2"});
	EXPECT_EQ(step.fields, (std::vector<std::string>{"0.25", "-0.5", "2"}));  // negative protected
	EXPECT_EQ(step.run(), 0);
	ASSERT_EQ(base.steps.size(), 1u);
	EXPECT_EQ(base.steps[0].v2_mps, -0.5);
	auto odo = parsed({"send", pty.slavePath(), "ODO?", "--json"});
	EXPECT_EQ(odo.run(), 0);
	EXPECT_EQ(odo.reply, (std::vector<std::string>{"0.5", "0", "0", "10", "-3", "2", "0"}));
}

TEST(SerialApp, SendReportsTheDevicesRefusalAndMissingPorts)
{
	fake::Base base;
	hw_serial::BaseHandler handler(base);
	hw_serial::PtyEmulator pty(handler);
	auto bad = parsed({"send", pty.slavePath(), "STEP", "1", "nan", "1"});
	EXPECT_EQ(bad.run(), 1);
	EXPECT_NE(bad.error.find("ERR BADARG STEP: field 2 'nan' is not a finite number"),
	          std::string::npos)
	    << bad.error;
	auto missing = parsed({"send", "/dev/mrolr-no-such-port", "ODO?"});
	EXPECT_EQ(missing.run(), 1);
	EXPECT_NE(missing.error.find("/dev/mrolr-no-such-port: cannot open the serial port"),
	          std::string::npos)
	    << missing.error;
}

TEST(SerialApp, BadArgumentsAreUsageErrors)
{
	EXPECT_THROW(parsed({}), util::UsageError);
	EXPECT_THROW(parsed({"fly"}), util::UsageError);
	EXPECT_THROW(parsed({"send", "/dev/pts/1"}), util::UsageError);
	EXPECT_THROW(parsed({"emulate", "extra"}), util::UsageError);
	EXPECT_THROW(parsed({"emulate", "--seconds", " -1"}), util::UsageError);
	EXPECT_THROW(parsed({"emulate", "--drop-probability", "1.5"}), util::UsageError);
	EXPECT_THROW(parsed({"send", "p", "ODO?", "--retries", "x"}), util::UsageError);
	EXPECT_TRUE(parsed({"--help"}).help_shown);
}

TEST(SerialApp, EmulateServesTheLabsDevicesAndCameraAndWritesTheTruth)
{
	const auto truth = std::filesystem::temp_directory_path() / "mrolr_serial_app_T.json";
	std::filesystem::remove(truth);
	auto app = parsed({"emulate", "--seconds", "0.2", "--json", "--truth-out", truth.string()});
	EXPECT_EQ(app.run(), 0);
	ASSERT_EQ(app.ports.size(), 4u);
	for (int i = 0; i < 3; ++i) EXPECT_EQ(app.ports[i].rfind("/dev/pts/", 0), 0u) << app.ports[i];
	EXPECT_NE(app.ports[0], app.ports[1]);
	EXPECT_EQ(app.ports[3].rfind("127.0.0.1:", 0), 0u) << app.ports[3];
	EXPECT_EQ(app.requests_served, 0u);
	// Nothing moved: the truth is the world's start (the lab's W0 at the origin, objects placed).
	const auto j = nlohmann::json::parse(std::ifstream(truth));
	EXPECT_DOUBLE_EQ(j["vehicle"]["z_m"].get<double>(), 0.0);
	EXPECT_TRUE(j["held"].is_null());
	EXPECT_GE(j["objects"].size(), 8u);
}

TEST(SerialApp, EmulateNamesAMissingConfigFile)
{
	auto app = parsed({"emulate", "--seconds", "0.1", "--sim", "/nonexistent/sim.ini"});
	try
	{
		app.run();
		FAIL() << "no throw";
	}
	catch (const std::runtime_error& e)
	{
		EXPECT_NE(std::string(e.what()).find("/nonexistent/sim.ini"), std::string::npos);
	}
}
