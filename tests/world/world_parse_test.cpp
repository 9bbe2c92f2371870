#include <mrolr/world/World.h>

#include "../common/ThrownMessage.h"

#include <gtest/gtest.h>

#include <cmath>

using mrolr::world::World;
using mrolr::world::WorldError;

namespace
{
const char* kPoints = R"(
# comment
[landmarks]
# name = X Y Z [known]
L1 = 1.20 2.10 3.50
L2 = -0.80 2.40 2.00 known   ; trailing comment
[waypoints]
W9 = 0 0 0
W1 = 2.0 0.5 30
W0 = -1, 1, -90
)";

std::string errorOf(const std::string& text)
{
	return mrolr::test_support::messageOf<WorldError>([&] { World::parse(text, "bad.ini"); },
	                                                  "no error");
}
}  // namespace

TEST(WorldParse, PointLandmarksAndWaypointsInFileOrder)
{
	const World w = World::parse(kPoints);
	ASSERT_EQ(w.landmarks.size(), 2u);
	EXPECT_EQ(w.landmarks[0].name, "L1");
	EXPECT_DOUBLE_EQ(w.landmarks[0].p_LinW.y(), 2.10);
	EXPECT_FALSE(w.landmarks[0].known);
	EXPECT_TRUE(w.landmarks[1].known);
	EXPECT_DOUBLE_EQ(w.landmarks[1].p_LinW.x(), -0.80);
	ASSERT_EQ(w.waypoints.size(), 3u);
	// file order, not alphabetical order
	EXPECT_EQ(w.waypoints[0].name, "W9");
	EXPECT_EQ(w.waypoints[1].name, "W1");
	EXPECT_EQ(w.waypoints[2].name, "W0");
	EXPECT_NEAR(w.waypoints[1].phi_rad, M_PI / 6, 1e-12);
	EXPECT_NEAR(w.waypoints[2].phi_rad, -M_PI / 2, 1e-12);
	EXPECT_DOUBLE_EQ(w.waypoints[2].x_m, 1.0);
	ASSERT_NE(w.findWaypoint("W1"), nullptr);
	EXPECT_EQ(w.findLandmark("nope"), nullptr);
}

TEST(WorldParse, MalformedLandmarkNamesFileLineSectionKeyValue)
{
	const std::string msg = errorOf("[landmarks]\nL1 = 1 2 3\nL7 = 1.0 abc 3\n");
	EXPECT_NE(msg.find("bad.ini:3"), std::string::npos) << msg;
	EXPECT_NE(msg.find("[landmarks]"), std::string::npos) << msg;
	EXPECT_NE(msg.find("L7"), std::string::npos) << msg;
	EXPECT_NE(msg.find("1.0 abc 3"), std::string::npos) << msg;
	EXPECT_NE(msg.find("'abc' is not a number"), std::string::npos) << msg;
}

TEST(WorldParse, OtherMalformedLinesAreRejected)
{
	EXPECT_NE(errorOf("[landmarks]\nL1 = 1 2 3 unknown\n").find("must be 'known'"),
	          std::string::npos);
	EXPECT_NE(errorOf("[landmarks]\nL1 = 1 2\n").find("X Y Z"), std::string::npos);
	EXPECT_NE(errorOf("[waypoints]\nW0 = 0 0\n").find("z x phi_deg"), std::string::npos);
	EXPECT_NE(errorOf("[waypoints]\nW0 = 0 0 0\nW0 = 1 1 1\n").find("defined twice"),
	          std::string::npos);
	EXPECT_NE(errorOf("L1 = 1 2 3\n").find("before any [section]"), std::string::npos);
	EXPECT_NE(errorOf("[landmarks]\nL1 1 2 3\n").find("key = value"), std::string::npos);
	EXPECT_NE(errorOf("[landmarks\n").find("malformed section"), std::string::npos);
}

TEST(WorldParse, MissingFileIsReported)
{
	try
	{
		World::load("/nonexistent/world.ini");
		FAIL() << "no error";
	}
	catch (const WorldError& e)
	{
		EXPECT_NE(std::string(e.what()).find("/nonexistent/world.ini"), std::string::npos);
	}
}
