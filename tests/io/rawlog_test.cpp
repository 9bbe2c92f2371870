#include <mrolr/io/Rawlog.h>

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>

using mrolr::io::RawlogRecord;
namespace fs = std::filesystem;

namespace
{
mrpt::img::CImage randomImage(std::mt19937& rng)
{
	mrpt::img::CImage img(64, 48, mrpt::img::CH_GRAY);
	for (int y = 0; y < 48; ++y)
		for (int x = 0; x < 64; ++x) *img(x, y) = uint8_t(rng() % 256);
	return img;
}

std::vector<RawlogRecord> sampleRecords()
{
	std::mt19937 rng(7);
	std::uniform_real_distribution<double> u(-1, 1);
	std::vector<RawlogRecord> v;
	for (int i = 0; i < 4; ++i)
	{
		RawlogRecord r;
		r.time_s = 0.5 * i;
		r.odometry_zxphi = {0.2 * i, 0.01 * i, 0.1 * u(rng)};
		r.true_zxphi = r.odometry_zxphi + Eigen::Vector3d(0.01, -0.02, 0.003);
		r.ticks_right = 1000 * i + 3, r.ticks_left = 990 * i - 2;
		r.head_rad = {u(rng), 0.3 * u(rng), -0.1, 0.1};
		r.has_stereo = i != 2;  // a step without images is allowed
		if (r.has_stereo) r.left = randomImage(rng), r.right = randomImage(rng);
		r.camera.ncols = 64, r.camera.nrows = 48;
		r.camera.fx(80), r.camera.fy(81), r.camera.cx(32), r.camera.cy(24);
		r.T_LcvInVehicle = Eigen::Translation3d(0.1, 0.125, 1.0) *
		                   Eigen::AngleAxisd(0.3 * i, Eigen::Vector3d::UnitY());
		r.T_RcvInLcv =
		    Eigen::Translation3d(0.25, 0, 0) * Eigen::AngleAxisd(0.1, Eigen::Vector3d::UnitY());
		v.push_back(r);
	}
	return v;
}

bool sameImage(const mrpt::img::CImage& a, const mrpt::img::CImage& b)
{
	if (a.getWidth() != b.getWidth() || a.getHeight() != b.getHeight()) return false;
	for (unsigned y = 0; y < a.getHeight(); ++y)
		for (unsigned x = 0; x < a.getWidth(); ++x)
			if (*a(x, y) != *b(x, y)) return false;
	return true;
}

std::string tempRawlog(const std::string& name)
{
	const fs::path dir =
	    fs::temp_directory_path() / ("mrolr_io_test_" + std::to_string(::getpid()));
	fs::create_directories(dir);
	return (dir / name).string();
}
}  // namespace

TEST(Rawlog, WrittenThenReadGivesTheSameObservations)
{
	const std::string path = tempRawlog("run.rawlog");
	const auto in = sampleRecords();
	{
		mrolr::io::RawlogWriter w(path);
		for (const auto& r : in) w.write(r);
		EXPECT_EQ(w.count(), in.size());
	}
	EXPECT_TRUE(fs::exists(mrolr::io::imagesDirFor(path) + "/BISIGHT_000000_left.png"));
	const auto out = mrolr::io::readRawlog(path);
	ASSERT_EQ(out.size(), in.size());
	for (size_t i = 0; i < in.size(); ++i)
	{
		EXPECT_NEAR(out[i].time_s, in[i].time_s, 1e-5);
		EXPECT_LT((out[i].odometry_zxphi - in[i].odometry_zxphi).norm(), 1e-9);
		ASSERT_TRUE(out[i].true_zxphi.has_value());
		EXPECT_LT((*out[i].true_zxphi - *in[i].true_zxphi).norm(), 1e-9);
		EXPECT_EQ(out[i].ticks_right, in[i].ticks_right);
		EXPECT_EQ(out[i].ticks_left, in[i].ticks_left);
		EXPECT_LT((out[i].head_rad - in[i].head_rad).norm(), 1e-12);
		ASSERT_EQ(out[i].has_stereo, in[i].has_stereo);
		if (!in[i].has_stereo) continue;
		EXPECT_TRUE(sameImage(out[i].left, in[i].left));
		EXPECT_TRUE(sameImage(out[i].right, in[i].right));
		EXPECT_DOUBLE_EQ(out[i].camera.fy(), 81);
		EXPECT_LT((out[i].T_LcvInVehicle.matrix() - in[i].T_LcvInVehicle.matrix()).norm(), 1e-9);
		EXPECT_LT((out[i].T_RcvInLcv.matrix() - in[i].T_RcvInLcv.matrix()).norm(), 1e-9);
	}
	fs::remove_all(fs::path(path).parent_path());
}

TEST(Rawlog, ReadWithPathsOnlyItNamesTheImagesThatHoldThePixels)
{
	const std::string path = tempRawlog("paths.rawlog");
	const auto in = sampleRecords();
	{
		mrolr::io::RawlogWriter w(path);
		for (const auto& r : in) w.write(r);
	}
	const auto out = mrolr::io::readRawlog(path, mrolr::io::ImageLoading::Paths);
	ASSERT_EQ(out.size(), in.size());
	size_t pairs = 0;
	for (size_t i = 0; i < in.size(); ++i)
	{
		ASSERT_EQ(out[i].has_stereo, in[i].has_stereo);
		if (!in[i].has_stereo) continue;
		++pairs;
		EXPECT_TRUE(out[i].left.isEmpty());  // nothing loaded
		mrpt::img::CImage left, right;
		ASSERT_TRUE(left.loadFromFile(out[i].left_file)) << out[i].left_file;
		ASSERT_TRUE(right.loadFromFile(out[i].right_file)) << out[i].right_file;
		EXPECT_TRUE(sameImage(left, in[i].left));
		EXPECT_TRUE(sameImage(right, in[i].right));
	}
	EXPECT_GT(pairs, 0u);
	fs::remove_all(fs::path(path).parent_path());
}

TEST(Rawlog, RawlogEditReadsIt)
{
	const std::string path = tempRawlog("info.rawlog");
	{
		mrolr::io::RawlogWriter w(path);
		for (const auto& r : sampleRecords()) w.write(r);
	}
	const std::string report = path + ".info.txt";
	const std::string cmd = "rawlog-edit --info -i '" + path + "' > '" + report + "' 2>&1";
	ASSERT_EQ(std::system(cmd.c_str()), 0) << cmd;
	std::ifstream f(report);
	std::stringstream ss;
	ss << f.rdbuf();
	const std::string text = ss.str();
	// rawlog-edit lists sensor labels with their counts: 3 stereo pairs, 4 of everything else
	for (const char* line : {"BISIGHT /      3", "GROUND_TRUTH /      4", "HEAD_ANGLES /      4",
	                         "ODOMETRY /      4", "Actions/SensoryFrame format       : Yes"})
		EXPECT_NE(text.find(line), std::string::npos) << line << " not listed in:\n" << text;
	fs::remove_all(fs::path(path).parent_path());
}

TEST(Rawlog, MissingFileIsReported)
{
	try
	{
		mrolr::io::readRawlog("/nonexistent/run.rawlog");
		FAIL() << "no error";
	}
	catch (const std::runtime_error& e)
	{
		EXPECT_NE(std::string(e.what()).find("/nonexistent/run.rawlog"), std::string::npos);
	}
}
