// The mission configuration is checked before anything moves, and errors name section and key.
#include "MissionTestConfig.h"

#include <mrolr/util/Config.h>

#include <gtest/gtest.h>

#include <sstream>

using namespace mrolr::mission;
using mrolr::util::ConfigError;

namespace
{
/** The message of the ConfigError that loading @p cfg throws ("" if none). */
std::string errorOf(const mrpt::config::CConfigFileBase& cfg)
{
	try
	{
		test::optionsFrom(cfg);
	}
	catch (const std::exception& e)
	{
		return e.what();
	}
	return "";
}

void expectError(const std::string& section, const std::string& key, const std::string& value,
                 const std::string& fragment)
{
	auto cfg = test::defaultMissionConfig();
	cfg.write(section, key, value);
	const auto msg = errorOf(cfg);
	EXPECT_NE(msg.find("[" + section + "] " + key), std::string::npos) << msg;
	EXPECT_NE(msg.find(fragment), std::string::npos) << msg;
}
}  // namespace

TEST(MissionOptions, DefaultConfigLoads)
{
	const auto o = test::optionsFrom(test::defaultMissionConfig());
	EXPECT_EQ(o.target, "alphabet_cube");
	EXPECT_TRUE(o.world.findObject(o.target));
	EXPECT_EQ(o.mode, NavigationMode::Slam);
	ASSERT_EQ(o.stations.size(), 2u);
	EXPECT_EQ(o.stations[0].name, "W5");
	EXPECT_NEAR(o.stations[1].xv_zxphi.z(), M_PI, 1e-12);
	EXPECT_EQ(o.home_waypoint, "W6");
	EXPECT_FALSE(o.world.objects.empty());
}

TEST(MissionOptions, SerialDriverNeedsItsPortAndBaud)
{
	auto cfg = test::defaultMissionConfig();
	cfg.write("device.arm", "driver", "serial");  // mission_sim.ini has no port for it
	EXPECT_NE(errorOf(cfg).find("[device.arm] port: missing"), std::string::npos) << errorOf(cfg);
	cfg.write("device.arm", "driver", "sim");
	cfg.write("device.head", "driver", "serial");
	cfg.write("device.head", "port", "/dev/ttyS9");
	EXPECT_NE(errorOf(cfg).find("[device.head] baud"), std::string::npos) << errorOf(cfg);
	cfg.write("device.head", "baud", "9600");
	cfg.write("device.head", "retries", "-1");
	EXPECT_NE(errorOf(cfg).find("[device.head] retries"), std::string::npos) << errorOf(cfg);
	cfg.write("device.head", "retries", "2");
	const auto o = test::optionsFrom(cfg);
	EXPECT_TRUE(o.devices.head.serial);
	EXPECT_FALSE(o.devices.base.serial);
	EXPECT_EQ(o.devices.head.link.port, "/dev/ttyS9");
	EXPECT_EQ(o.devices.head.link.link.retries, 2);
	EXPECT_EQ(o.devices.head.link.link.device, "device.head");
}

TEST(MissionOptions, TheShippedHardwareConfigLoadsWithSerialDevices)
{
	const auto o = MissionOptions::load(test::configDir() + "/mission_hw.ini");
	for (const auto* d : {&o.devices.base, &o.devices.head, &o.devices.arm})
	{
		EXPECT_TRUE(d->serial) << d->section;
		EXPECT_EQ(d->link.link.device, d->section);
		EXPECT_NE(d->port_key.find("mission_hw.ini [" + d->section + "] port"), std::string::npos);
	}
	EXPECT_EQ(o.target, test::optionsFrom(test::defaultMissionConfig()).target);
	std::ostringstream dump;
	o.dump(dump);
	EXPECT_NE(dump.str().find("[device.arm]\ndriver = serial\nport = /dev/ttyUSB2"),
	          std::string::npos)
	    << dump.str();
}

TEST(MissionOptions, UnknownDriverNamesTheChoices)
{
	expectError("device.base", "driver", "usb", "sim, serial");
}

TEST(MissionOptions, BadModeTargetWaypointAndStation)
{
	expectError("mission", "mode", "fast", "slam or dead_reckoning");
	expectError("mission", "target", "teapot", "no model 'teapot'");
	expectError("mission", "route", "W0 W99", "no waypoint 'W99'");
	expectError("mission", "search_stations", "W5; 1 2", "neither a waypoint name");
}

TEST(MissionOptions, ObstacleModeReadsItsSection)
{
	auto cfg = test::defaultMissionConfig();  // obstacle_mode = false and no [obstacle]
	EXPECT_FALSE(test::optionsFrom(cfg).obstacle_mode);
	cfg.write("mission", "obstacle_mode", "true");
	EXPECT_NE(errorOf(cfg).find("[obstacle] tilt_deg"), std::string::npos) << errorOf(cfg);
	const auto o = MissionOptions::load(test::configDir() + "/mission_obstacle.ini");
	EXPECT_TRUE(o.obstacle_mode);
	EXPECT_DOUBLE_EQ(o.obstacle.range_m, 1.0);
	EXPECT_EQ(o.world.obstacles.size(), 3u);
}

TEST(MissionOptions, MalformedNumbersAndMissingKeys)
{
	expectError("navigation", "max_range_m", "far", "max_range_m");
	expectError("search", "pan_step_deg", "0", "pan_step_deg");
	auto cfg = test::defaultMissionConfig();
	cfg.write("mission", "world_file", "../maps/nowhere/world.ini");
	EXPECT_NE(errorOf(cfg) + "x", "x");  // WorldError or ConfigError, never silence
}

TEST(MissionOptions, MissingFileNamesTheKey)
{
	expectError("files", "arm_file", "no_such_arm.ini", "cannot open");
}

TEST(MissionOptions, SceneSourceIsSimulatedOrReconstructedWithItsSceneFile)
{
	auto cfg = test::defaultMissionConfig();
	const auto o = test::optionsFrom(cfg);
	EXPECT_EQ(o.search.scene_source, "reconstructed");  // the default mission's
	EXPECT_GT(o.scene.max_depth_mm, o.scene.min_depth_mm);
	EXPECT_TRUE(o.search.image_verification);
	EXPECT_GT(o.image_verification.min_score, 0);
	expectError("search", "scene_source", "guessed", "simulated, reconstructed");
	cfg.write("files", "scene_file", "no_such_scene.ini");
	EXPECT_NE(errorOf(cfg).find("[files] scene_file"), std::string::npos) << errorOf(cfg);
	cfg.write("search", "scene_source", "simulated");  // then the scene file is not read
	EXPECT_EQ(test::optionsFrom(cfg).search.scene_source, "simulated");
}

TEST(MissionOptions, MeasurementSourceIsIdealOrImagesWithTheVisionFile)
{
	const auto ideal = test::optionsFrom(test::defaultMissionConfig());
	EXPECT_EQ(ideal.navigation.measurement_source, "ideal");
	expectError("navigation", "measurement_source", "camera", "ideal, images");
	auto cfg = test::defaultMissionConfig();
	cfg.write("navigation", "measurement_source", "images");
	cfg.write("files", "vision_file", "no_such_vision.ini");
	EXPECT_NE(errorOf(cfg).find("[files] vision_file"), std::string::npos) << errorOf(cfg);
	cfg.write("files", "vision_file", "slam.ini");
	const auto o = test::optionsFrom(cfg);
	// The filter takes the vision file's R (image measurements), the head constants stay.
	EXPECT_DOUBLE_EQ(o.slam.std_pan_rad, 0.001);
	EXPECT_NE(o.slam.std_elevation_rad, ideal.slam.std_elevation_rad);
	EXPECT_EQ(o.slam.head.constants.head_height_m, ideal.slam.head.constants.head_height_m);
	EXPECT_EQ(o.vision.patch_size_px, 13);
}

TEST(MissionOptions, TurnStepsAndReversingAreOptionalNavigationKeys)
{
	const auto o = test::optionsFrom(test::defaultMissionConfig());
	EXPECT_DOUBLE_EQ(o.trajectory.max_rotation_step_deg, o.navigation.max_rotation_step_deg);
	EXPECT_GT(o.navigation.reverse_max_m, 0);
	expectError("navigation", "reverse_max_m", "-1", "reverse_max_m");
	expectError("navigation", "max_rotation_step_deg", "400", "max_rotation_step_deg");
}

TEST(MissionOptions, TheObstacleMissionNavigatesAsTheDefaultMission)
{
	// config/mission_obstacle.ini is mission_sim.ini plus obstacle mode: the same [navigation], so
	// its turns are split into the same measured steps (without them the half-turns at the detour
	// waypoints ended 20-40 deg off and the estimate jumped). Not compared: reversing, which
	// obstacle mode never does, and the image-measurement key (ideal measurements here).
	auto sim = test::optionsFrom(test::defaultMissionConfig());
	auto obstacle = test::optionsFrom(test::missionConfig("mission_obstacle.ini"));
	ASSERT_TRUE(obstacle.obstacle_mode);
	ASSERT_EQ(obstacle.navigation.measurement_source, "ideal");
	for (auto* o : {&sim, &obstacle})
		o->navigation.reverse_max_m = 0, o->navigation.image_nssd_ambiguity_margin = -1;
	std::ostringstream a, b;
	sim.navigation.dump(a);
	obstacle.navigation.dump(b);
	EXPECT_EQ(a.str(), b.str());
	EXPECT_DOUBLE_EQ(obstacle.trajectory.max_rotation_step_deg,
	                 sim.trajectory.max_rotation_step_deg);
	EXPECT_LT(obstacle.trajectory.max_rotation_step_deg, 90);
}
