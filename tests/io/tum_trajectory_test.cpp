// TUM trajectories (io/TumTrajectory.h): MRPT's axes, a lossless round trip, errors named.
#include <mrolr/io/TumTrajectory.h>

#include "../common/ThrownMessage.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>

using namespace mrolr;
namespace fs = std::filesystem;

namespace
{
std::string tmp(const std::string& name)
{
	return (fs::temp_directory_path() / ("mrolr_tum_test_" + name)).string();
}

void writeText(const std::string& path, const std::string& text)
{
	std::ofstream(path) << text;
}

std::string errorOf(const std::function<void()>& f)
{
	return mrolr::test_support::messageOf<std::exception>(f);
}
}  // namespace

TEST(TumTrajectory, ALineIsTheVehicleInMrptAxes)
{
	// x_v = (z, x, φ) = (1, 2, 90°): MRPT x = 1, y = 2, on the floor, yaw 90° about the vertical
	std::istringstream in(io::tumLine({12.5, {1, 2, M_PI / 2}}));
	double v[8];
	for (double& x : v) ASSERT_TRUE(in >> x);
	const double h = std::sqrt(0.5);
	const double expected[8] = {12.5, 1, 2, 0, 0, 0, h, h};
	for (int i = 0; i < 8; ++i) EXPECT_NEAR(v[i], expected[i], 1e-12) << i;
}

TEST(TumTrajectory, RoundTripKeepsTimeAndState)
{
	std::mt19937 rng(5);
	std::uniform_real_distribution<double> u(-10, 10), yaw(-M_PI, M_PI);
	std::vector<io::StampedVehicle> poses;
	double t = 100;
	for (int i = 0; i < 500; ++i) poses.push_back({t += 0.1, {u(rng), u(rng), yaw(rng)}});
	poses.push_back({t + 1, {0, 0, M_PI}});  // the wrap
	const auto path = tmp("round_trip.tum");
	io::writeTum(path, poses);
	const auto back = io::readTum(path);
	ASSERT_EQ(back.size(), poses.size());
	for (size_t i = 0; i < poses.size(); ++i)
	{
		EXPECT_NEAR(back[i].time_s, poses[i].time_s, 1e-9);
		EXPECT_NEAR(back[i].xv_zxphi.x(), poses[i].xv_zxphi.x(), 1e-9);
		EXPECT_NEAR(back[i].xv_zxphi.y(), poses[i].xv_zxphi.y(), 1e-9);
		EXPECT_NEAR(std::remainder(back[i].xv_zxphi.z() - poses[i].xv_zxphi.z(), 2 * M_PI), 0,
		            1e-9);
	}
	fs::remove(path);
}

TEST(TumTrajectory, BadValuesAndLinesAreNamed)
{
	const auto path = tmp("bad.tum");
	EXPECT_NE(errorOf([&] { io::writeTum(path, {{0, {0, 0, 0}}, {1, {NAN, 0, 0}}}); })
	              .find("pose 1 is not finite"),
	          std::string::npos);
	EXPECT_NE(errorOf([&] { io::writeTum(path, {{2, {0, 0, 0}}, {1, {0, 0, 0}}}); })
	              .find("goes back"),
	          std::string::npos);
	EXPECT_NE(errorOf([&] { io::writeTum("/nonexistent_dir_mrolr/x.tum", {}); })
	              .find("/nonexistent_dir_mrolr/x.tum"),
	          std::string::npos);
	const std::pair<const char*, const char*> cases[] = {
	    {"# c\n1 2 3 0 0 0 0 1\n1 2 3\n", ":3: expected 8 numbers"},
	    {"1 2 3 0 0 0 0 1 extra\n", ":1: trailing 'extra'"},
	    {"1 2 3 0.5 0 0 0 1\n", ":1: not a planar pose"},
	    {"1 2 3 0 0.6 0 0 0.8\n", ":1: not a planar pose"},
	    {"1 2 3 0 0 0 0 2\n", ":1: the quaternion is not a unit one"},
	    {"1 2 3 0 0 0 zero 1\n", ":1: expected 8 numbers"}};
	for (const auto& [text, expected] : cases)
	{
		writeText(path, text);
		const auto e = errorOf([&] { io::readTum(path); });
		EXPECT_NE(e.find(path + expected), std::string::npos) << text << " -> " << e;
	}
	EXPECT_NE(errorOf([&] { io::readTum(tmp("missing.tum")); }).find("missing.tum"),
	          std::string::npos);
	fs::remove(path);
}
