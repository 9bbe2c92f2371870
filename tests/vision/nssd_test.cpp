// NSSD (thesis eq 5.21): invariance to brightness, rejection of wrong patches, and the OpenCV
// route (matchTemplate, N = 2(1 - rho)) against the literal formula.
#include <mrolr/vision/Nssd.h>
#include <mrolr/vision/PatchSearch.h>
#include <mrolr/vision/ShiTomasi.h>
#include <mrolr/vision/SyntheticStereoHead.h>
#include <mrolr/vision/VisionError.h>

#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>

#include <cmath>

using namespace mrolr::vision;

namespace
{
/** A 200x160 image: grey noise background with two different textures at known centres. */
cv::Mat twoTextureImage(cv::Point a, cv::Point b)
{
	cv::Mat im(160, 200, CV_8UC1, cv::Scalar(90));
	cv::RNG rng(7);
	cv::Mat noise(im.size(), CV_8UC1);
	rng.fill(noise, cv::RNG::NORMAL, 0, 2);
	im += noise;
	makeTexture(31, 11).copyTo(im(cv::Rect(a.x - 15, a.y - 15, 31, 31)));
	makeTexture(31, 12).copyTo(im(cv::Rect(b.x - 15, b.y - 15, 31, 31)));
	return im;
}

cv::Mat scaled(const cv::Mat& im, double gain)
{
	cv::Mat out;
	im.convertTo(out, CV_8UC1, gain);
	return out;
}
}  // namespace

TEST(Nssd, ZeroForIdenticalAndInvariantToGainAndOffset)
{
	const cv::Mat p = makeTexture(13, 3);
	EXPECT_NEAR(nssd(p, p), 0.0, 1e-12);
	cv::Mat q;
	p.convertTo(q, CV_32F, 0.5, 40.0);
	cv::Mat p32;
	p.convertTo(p32, CV_32F);
	EXPECT_NEAR(nssd(p32, q), 0.0, 1e-9);
}

TEST(Nssd, BoundedAndLargeForUnrelatedPatches)
{
	const cv::Mat a = makeTexture(13, 1), b = makeTexture(13, 2);
	const double n = nssd(a, b);
	EXPECT_GT(n, 0.9);
	EXPECT_LE(n, 4.0);
	cv::Mat inverted = 255 - a;
	EXPECT_NEAR(nssd(a, inverted), 4.0, 1e-9);  // rho = -1
}

TEST(Nssd, OpenCvMapEqualsLiteralFormula)
{
	const cv::Mat im = twoTextureImage({60, 70}, {140, 80});
	const cv::Mat patch = extractPatch(im, {60, 70}, 13);
	const cv::Mat a = nssdMap(im, patch, NssdMethod::OpenCv);
	const cv::Mat b = nssdMap(im, patch, NssdMethod::Direct);
	ASSERT_EQ(a.size(), b.size());
	ASSERT_EQ(a.size(), cv::Size(200 - 12, 160 - 12));
	double worst = 0;
	cv::minMaxLoc(cv::abs(a - b), nullptr, &worst);
	EXPECT_LT(worst, 1e-3);
	EXPECT_NEAR(a.at<float>(70 - 6, 60 - 6), 0.0, 1e-4);
}

TEST(Nssd, AcceptsRightPatchUnderTenPercentBrightnessChange)
{
	const cv::Point right(60, 70), wrong(140, 80);
	const cv::Mat im = twoTextureImage(right, wrong);
	const cv::Mat saved = extractPatch(im, {right.x, right.y}, 13);
	for (double gain : {0.9, 1.1})
	{
		const PatchMatch m =
		    searchSquare(scaled(im, gain), saved, {right.x + 3, right.y - 2}, 20, 0.9);
		ASSERT_TRUE(m.found) << "gain " << gain << " best " << m.score;
		EXPECT_LT(m.score, 0.1);
		EXPECT_NEAR(m.uv.x(), right.x, 0.5);
		EXPECT_NEAR(m.uv.y(), right.y, 0.5);
	}
}

TEST(Nssd, RejectsWrongPatchUnderTenPercentBrightnessChange)
{
	const cv::Point right(60, 70), wrong(140, 80);
	const cv::Mat im = twoTextureImage(right, wrong);
	const cv::Mat other = makeTexture(31, 99)(cv::Rect(9, 9, 13, 13)).clone();
	for (double gain : {0.9, 1.0, 1.1})
	{
		const PatchMatch m = searchSquare(scaled(im, gain), other, {right.x, right.y}, 20, 0.9);
		EXPECT_FALSE(m.found) << "gain " << gain << " best " << m.score;
		EXPECT_GT(m.candidates, 1000);
	}
}

TEST(Nssd, BadInputIsReported)
{
	const cv::Mat flat(13, 13, CV_8UC1, cv::Scalar(50));
	EXPECT_THROW(nssd(flat, makeTexture(13, 1)), VisionError);
	EXPECT_THROW(nssd(makeTexture(13, 1), makeTexture(15, 1)), VisionError);
	EXPECT_THROW(nssdMap(makeTexture(13, 1), makeTexture(15, 2)), VisionError);
	cv::Mat color(20, 20, CV_8UC3);
	EXPECT_THROW(nssdMap(color, makeTexture(13, 1)), VisionError);
}

// Ambiguity (nssd_ambiguity_margin): the same texture twice in the region gives a rival score as
// good as the best; two different textures leave a wide gap.
TEST(Nssd, SecondScoreSeesARepeatedTexture)
{
	const cv::Point a{60, 80}, b{140, 80};
	cv::Mat twice = twoTextureImage(a, b);
	makeTexture(31, 11).copyTo(twice(cv::Rect(b.x - 15, b.y - 15, 31, 31)));
	const cv::Mat saved = twice(cv::Rect(a.x - 6, a.y - 6, 13, 13)).clone();
	const PatchMatch rep = searchSquare(twice, saved, {100, 80}, 60, 0.9);
	ASSERT_TRUE(rep.found);
	EXPECT_LT(rep.second_score - rep.score, 0.05);
	const PatchMatch one = searchSquare(twoTextureImage(a, b), saved, {100, 80}, 60, 0.9);
	ASSERT_TRUE(one.found);
	EXPECT_LT((one.uv - Eigen::Vector2d(a.x, a.y)).norm(), 1.0);
	EXPECT_GT(one.second_score - one.score, 0.3);
}

TEST(Nssd, SecondScoreIsInfiniteWithoutRivals)
{
	const cv::Mat im = twoTextureImage({60, 80}, {140, 80});
	const cv::Mat saved = im(cv::Rect(54, 74, 13, 13)).clone();
	const PatchMatch m = searchSquare(im, saved, {60, 80}, 3, 0.9);
	ASSERT_TRUE(m.found);
	EXPECT_TRUE(std::isinf(m.second_score));
}
