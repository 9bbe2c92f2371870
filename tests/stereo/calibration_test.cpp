#include <mrolr/stereo/CheckerboardCalibration.h>

#include <mrpt/config/CConfigFileMemory.h>

#include <gtest/gtest.h>
#include <opencv2/calib3d.hpp>
#include <opencv2/imgproc.hpp>

#include <cstdio>

using namespace mrolr::stereo;

namespace
{
const std::string kDir = "/usr/share/mrpt/datasets/stereo-calib/";

std::vector<std::string> files(const char* side)
{
	std::vector<std::string> out;
	for (int i = 0; i < 4; ++i) out.push_back(kDir + std::to_string(i) + "_" + side + ".jpg");
	return out;
}

/** A white-bordered checkerboard texture with @p px pixels per square. */
cv::Mat boardTexture(const BoardSpec& b, int px)
{
	cv::Mat tex((b.rows + 3) * px, (b.cols + 3) * px, CV_8U, cv::Scalar(255));
	for (int r = 0; r < b.rows + 1; ++r)
		for (int c = 0; c < b.cols + 1; ++c)
			if ((r + c) % 2 == 0) tex(cv::Rect((c + 1) * px, (r + 1) * px, px, px)) = 0;
	return tex;
}

/** Renders the board seen by camera K at board pose (rvec, tvec) in that camera (mm). */
cv::Mat render(const BoardSpec& b, const cv::Matx33d& K, const cv::Vec3d& rvec, const cv::Vec3d& t)
{
	const int px = 40;
	const cv::Mat tex = boardTexture(b, px);
	cv::Matx33d R;
	cv::Rodrigues(rvec, R);
	// texture pixel (u, v) -> board mm ((u - 2 px) s / px, ...): the first inner corner is at 2 px.
	const double s = b.square_mm / px;
	const cv::Matx33d A(s, 0, -2 * px * s, 0, s, -2 * px * s, 0, 0, 1);
	const cv::Matx33d H =
	    K * cv::Matx33d(R(0, 0), R(0, 1), t[0], R(1, 0), R(1, 1), t[1], R(2, 0), R(2, 1), t[2]) * A;
	cv::Mat img;
	cv::warpPerspective(tex, img, cv::Mat(H), {640, 480}, cv::INTER_AREA, cv::BORDER_CONSTANT, 160);
	cv::GaussianBlur(img, img, {3, 3}, 0.7);
	return img;
}
}  // namespace

TEST(StereoCalibration, CalibratesMrptRealPairsBelowHalfPixel)
{
	const StereoCalibration c = calibrateStereo(files("left"), files("right"), {9, 6, 34.0});
	EXPECT_EQ(c.pairs_used, 4);
	EXPECT_LT(c.rms_px, 0.5);
	// MRPT's own unit test for these BumbleBee2 images: right camera 119.4 mm to the side.
	EXPECT_NEAR(c.baseline_mm(), 119.4, 5.0);
	EXPECT_NEAR(c.K_left(0, 0), c.K_left(1, 1), 0.02 * c.K_left(0, 0));
	EXPECT_EQ(c.image_size, cv::Size(1024, 768));
}

TEST(StereoCalibration, RecoversKnownCalibrationOfRenderedBoards)
{
	const BoardSpec b{9, 6, 30.0};
	const cv::Matx33d K(600, 0, 320, 0, 600, 240, 0, 0, 1);
	const cv::Vec3d t_LinR(-100, 0, 0);  // right camera 100 mm to the right, parallel
	std::vector<cv::Mat> L, R;
	const double tilts[][3] = {{0.3, 0.2, 0},      {-0.3, 0.25, 0.1}, {0.2, -0.35, -0.1},
	                           {-0.25, -0.2, 0.2}, {0.4, 0, 0.05},    {0, 0.4, -0.05}};
	for (const auto& tl : tilts)
	{
		const cv::Vec3d rv(tl[0], tl[1], tl[2]), t(-80, -60, 700);
		L.push_back(render(b, K, rv, t));
		R.push_back(render(b, K, rv, t + t_LinR));
	}
	const StereoCalibration c = calibrateStereo(L, R, b);
	EXPECT_EQ(c.pairs_used, 6);
	EXPECT_LT(c.rms_px, 0.3);
	EXPECT_NEAR(c.K_left(0, 0), 600, 6);
	EXPECT_NEAR(c.K_right(1, 1), 600, 6);
	EXPECT_NEAR(c.baseline_mm(), 100, 1.5);
	EXPECT_NEAR(c.t_LinR_mm[0], -100, 1.5);
}

TEST(StereoCalibration, IniRoundTripAndStrictLoading)
{
	StereoCalibration c;
	c.image_size = {640, 480};
	c.K_left = cv::Matx33d(1.0 / 3, 0, 320, 0, 500, 240, 0, 0, 1);
	c.t_LinR_mm = {-119.4, 0.1, 2.0 / 3};
	c.rms_px = 0.123;
	c.pairs_used = 4;
	const std::string path = ::testing::TempDir() + "calib_rt.ini";
	saveStereoCalibration(c, path);
	const StereoCalibration d = loadStereoCalibration(path);
	EXPECT_EQ(d.K_left, c.K_left);
	EXPECT_EQ(d.t_LinR_mm, c.t_LinR_mm);
	EXPECT_EQ(d.image_size, c.image_size);
	EXPECT_EQ(d.pairs_used, 4);
	std::remove(path.c_str());

	mrpt::config::CConfigFileMemory bad;
	c.saveToConfigFile(bad, "s");
	bad.write("s", "R_RfromL", "1 0 0 0 1 0 0 0 2");
	StereoCalibration e;
	try
	{
		e.loadFromConfigFile(bad, "s");
		ADD_FAILURE() << "a non-rotation was accepted";
	}
	catch (const std::exception& ex)
	{
		EXPECT_NE(std::string(ex.what()).find("R_RfromL"), std::string::npos);
	}
	bad.write("s", "K_left_px", "1 2 3");
	EXPECT_THROW(e.loadFromConfigFile(bad, "s"), std::exception);
	EXPECT_THROW(loadStereoCalibration("/nonexistent.ini"), std::runtime_error);
}

TEST(StereoCalibration, WrongBoardSizeIsAnErrorNamingTheBoard)
{
	EXPECT_THROW(parseBoardSize("9by6", 30), std::invalid_argument);
	EXPECT_THROW(parseBoardSize("9x6", -1), std::invalid_argument);
	EXPECT_EQ(parseBoardSize("7X5", 20).rows, 5);
	try
	{
		calibrateStereo(files("left"), files("right"), {5, 11, 34.0});
		ADD_FAILURE();
	}
	catch (const std::runtime_error& e)
	{
		EXPECT_NE(std::string(e.what()).find("5x11"), std::string::npos);
	}
	EXPECT_THROW(calibrateStereo({kDir + "nope.jpg"}, {kDir + "nope.jpg"}, {}), std::runtime_error);
}
