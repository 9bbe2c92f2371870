#include <mrolr/world/World.h>

#include "../common/ThrownMessage.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>

using mrolr::world::World;
using mrolr::world::WorldError;

namespace
{
const std::string kLab = std::string(MROLR_SOURCE_DIR) + "/maps/lab/world.ini";

const char* kBase = R"(
[room]
min_m = -3 0 -2
max_m = 3 3 6
[waypoints]
W0 = 0 0 0
[table.t]
centre_m = 0 1.5
size_m = 1.0 0.8 0.75
)";

std::string errorOf(const std::string& extra)
{
	return mrolr::test_support::messageOf<WorldError>(
	    [&] { World::parse(std::string(kBase) + extra, "lab.ini"); }, "no error");
}
}  // namespace

TEST(WorldScenery, ShippedLabHasWhatTheIssueAsks)
{
	const World w = World::load(kLab);
	ASSERT_TRUE(w.has_room);
	const auto size = w.room.max_m - w.room.min_m;
	EXPECT_NEAR(size.x() * size.z(), 48, 10);  // about 8 x 6 m
	EXPECT_GE(w.patches.size(), 12u);
	const auto onCeiling =
	    std::count_if(w.patches.begin(), w.patches.end(),
	                  [&](const auto& p) { return p.centre_m.y() > w.room.max_m.y() - 0.05; });
	EXPECT_GE(onCeiling, 2);
	const auto* sign = w.findLandmark("fire_sign");
	ASSERT_NE(sign, nullptr);
	EXPECT_TRUE(sign->known);
	ASSERT_EQ(w.tables.size(), 1u);
	EXPECT_NEAR(w.tables[0].z_m, 1.5, 0.3);
	EXPECT_GE(w.objects.size(), 6u);
	ASSERT_NE(w.findObject(w.mission.target), nullptr);
	ASSERT_NE(w.findWaypoint(w.mission.table_waypoint), nullptr);
	for (const auto& p : w.patches)  // every patch lies inside the room
		EXPECT_TRUE((p.centre_m.array() >= w.room.min_m.array()).all() &&
		            (p.centre_m.array() <= w.room.max_m.array()).all())
		    << p.name;
}

TEST(WorldScenery, ObjectsOnTheLabTableAreSpacedAsIn722)
{
	const World w = World::load(kLab);
	for (size_t i = 0; i < w.objects.size(); ++i)
		for (size_t j = 0; j < i; ++j)
		{
			const double d = std::hypot(w.objects[i].x_m - w.objects[j].x_m,
			                            w.objects[i].z_m - w.objects[j].z_m);
			// centres at least two object sizes (<= 0.16 m) apart: gaps >= the largest size
			EXPECT_GE(d, 0.32) << w.objects[i].name << " / " << w.objects[j].name;
		}
}

TEST(WorldScenery, PatchIsAlsoAPointLandmark)
{
	const World w = World::parse(std::string(kBase) + R"(
[patch.sign]
centre_m = 1 1.5 5.99
normal = 0 0 -1
up = 0 1 0
size_m = 0.3 0.3
texture = procedural:fire_sign
known = true
)");
	ASSERT_EQ(w.landmarks.size(), 1u);
	EXPECT_EQ(w.landmarks[0].name, "sign");
	EXPECT_TRUE(w.landmarks[0].known);
	EXPECT_DOUBLE_EQ(w.landmarks[0].p_LinW.z(), 5.99);
}

TEST(WorldScenery, ErrorsNameFileSectionKeyAndValue)
{
	std::string m = errorOf("[object.cup]\nmodel = cup\ntable = t\nposition_m = 0 3.0\n");
	EXPECT_NE(m.find("lab.ini:"), std::string::npos) << m;
	EXPECT_NE(m.find("[object.cup] position_m = '0 3.0'"), std::string::npos) << m;
	EXPECT_NE(m.find("not on the top"), std::string::npos) << m;
	m = errorOf("[object.cup]\nmodel = cup\ntable = nope\nposition_m = 0 1.5\n");
	EXPECT_NE(m.find("[object.cup] table = 'nope'"), std::string::npos) << m;
	m = errorOf("[obstacle.box]\ncentre_m = 1 1\nsize_m = 1 -1 1\n");
	EXPECT_NE(m.find("[obstacle.box] size_m"), std::string::npos) << m;
	m = errorOf("[obstacle.box]\ncentre_m = 1 1\nsize_m = 1 1 1\ncolor = 1 0 0\n");
	EXPECT_NE(m.find("[obstacle.box] color"), std::string::npos) << m;
	EXPECT_NE(m.find("unknown key"), std::string::npos) << m;
	m = errorOf(
	    "[patch.p]\ncentre_m = 0 1 5\nnormal = 0 0 -1\nup = 0 0 1\nsize_m = 1 1\n"
	    "texture = x.png\n");
	EXPECT_NE(m.find("perpendicular"), std::string::npos) << m;
	m = errorOf("[mission]\ntarget = ghost\ntable_waypoint = W0\nhome_waypoint = W0\n");
	EXPECT_NE(m.find("[mission] target = 'ghost'"), std::string::npos) << m;
	m = errorOf("[tables.t2]\n");
	EXPECT_NE(m.find("unknown section"), std::string::npos) << m;
	m = errorOf("[table.u]\ncentre_m = 0 1.5\n");
	EXPECT_NE(m.find("[table.u] size_m: missing key"), std::string::npos) << m;
}

TEST(WorldScenery, EveryShippedWorldLoads)
{
	// the point-landmark worlds of the EKF simulator and the full lab share one format
	int count = 0;
	for (const auto& e :
		 std::filesystem::directory_iterator(std::string(MROLR_SOURCE_DIR) + "/maps"))
	{
		const auto file = e.path() / "world.ini";
		if (!std::filesystem::exists(file)) continue;
		const World w = World::load(file.string());
		EXPECT_FALSE(w.landmarks.empty()) << file;
		EXPECT_GE(w.waypoints.size(), 2u) << file;
		++count;
	}
	EXPECT_GE(count, 1);
}
