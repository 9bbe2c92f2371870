// Known features (thesis 5.6.2): the shipped maps/lab plan's section loads, save/load round-trips, and
// malformed entries are reported with file, section and key.
#include <mrolr/util/Config.h>
#include <mrolr/vision/KnownFeatures.h>
#include <mrolr/vision/SyntheticStereoHead.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>

using namespace mrolr::vision;

TEST(KnownFeatures, ShippedLabPlanHasTheFireSignWhereTheRobotTriangulatedIt)
{
	// The plan's lines carry three sigmas after the PNG; they are read past.
	const auto known = loadKnownFeatures(std::string(MROLR_SOURCE_DIR) + "/maps/lab/plan.ini");
	const auto fire =
	    std::find_if(known.begin(), known.end(), [](auto& f) { return f.id == "fire_sign"; });
	ASSERT_NE(fire, known.end());
	// The sign is on the far wall (z = 6 m in the world); the robot's own triangulation is near it
	// but not equal to it.
	EXPECT_NEAR(fire->p_FinW.z(), 5.99, 0.1);
	EXPECT_GT(std::abs(fire->p_FinW.z() - 5.99), 1e-6);
	for (const auto& f : known) EXPECT_EQ(f.patch.size(), cv::Size(13, 13)) << f.id;
}

TEST(KnownFeatures, SaveLoadRoundTrip)
{
	const auto dir = std::filesystem::temp_directory_path() / "mrolr_known_test";
	const std::string path = (dir / "known_features.ini").string();
	const std::vector<KnownFeature> in{{"a", {1, 2, 3}, makeTexture(13, 1)},
	                                   {"b", {-0.5, 1.5, 4.25}, makeTexture(13, 2)}};
	saveKnownFeatures(path, in);
	auto out = loadKnownFeatures(path);
	ASSERT_EQ(out.size(), 2u);
	std::sort(out.begin(), out.end(), [](auto& x, auto& y) { return x.id < y.id; });
	for (size_t i = 0; i < 2; ++i)
	{
		EXPECT_EQ(out[i].id, in[i].id);
		EXPECT_LT((out[i].p_FinW - in[i].p_FinW).norm(), 1e-9);
		EXPECT_EQ(cv::norm(out[i].patch, in[i].patch, cv::NORM_INF), 0.0);
	}
}

TEST(KnownFeatures, MalformedEntriesNameTheKey)
{
	const auto dir = std::filesystem::temp_directory_path() / "mrolr_known_bad";
	std::filesystem::create_directories(dir);
	const std::string path = (dir / "known_features.ini").string();
	for (const std::string line : {"x = 1 2 three p.png", "x = 1 2 3", "x = 1 2 3 missing.png",
	                               "x = 1 2 3 p.png 0.1 wide 0.1", "x = 1 2 3 p.png 0.1 0.1"})
	{
		std::ofstream(path) << "[known_features]\n" << line << "\n";
		try
		{
			loadKnownFeatures(path);
			FAIL() << "accepted: " << line;
		}
		catch (const mrolr::util::ConfigError& e)
		{
			EXPECT_NE(std::string(e.what()).find("[known_features] x"), std::string::npos)
			    << e.what();
		}
	}
	EXPECT_THROW(loadKnownFeatures((dir / "none.ini").string()), mrolr::util::ConfigError);
}
