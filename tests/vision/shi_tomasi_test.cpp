// Shi-Tomasi acquisition (thesis eq 5.20): the best patch of a box lies on the texture, flat boxes
// give nothing, patches outside the image are refused.
#include <mrolr/vision/ShiTomasi.h>
#include <mrolr/vision/SyntheticStereoHead.h>
#include <mrolr/vision/VisionError.h>

#include <gtest/gtest.h>

using namespace mrolr::vision;

namespace
{
cv::Mat sceneWithTextureAt(cv::Point c)
{
	cv::Mat im(240, 320, CV_8UC1, cv::Scalar(90));
	makeTexture(21, 5).copyTo(im(cv::Rect(c.x - 10, c.y - 10, 21, 21)));
	return im;
}
}  // namespace

TEST(ShiTomasi, BestCornerOfTheBoxLiesOnTheTexture)
{
	const cv::Mat im = sceneWithTextureAt({200, 100});
	const auto c = bestCornerInBox(im, cv::Rect(150, 50, 100, 100), 13, 1e-4);
	ASSERT_TRUE(c.has_value());
	EXPECT_LE(std::abs(c->uv.x() - 200), 16);
	EXPECT_LE(std::abs(c->uv.y() - 100), 16);
	// λ_min at the winner is the maximum of the full-image map inside the box
	const cv::Mat full = minEigenvalueMap(im, 13);
	EXPECT_NEAR(c->min_eigenvalue, full.at<float>(int(c->uv.y()), int(c->uv.x())), 1e-6);
}

TEST(ShiTomasi, FlatBoxOrBoxOutsideGivesNothing)
{
	const cv::Mat im = sceneWithTextureAt({200, 100});
	EXPECT_FALSE(bestCornerInBox(im, cv::Rect(10, 130, 80, 80), 13, 1e-4).has_value());
	EXPECT_FALSE(bestCornerInBox(im, cv::Rect(400, 400, 50, 50), 13, 1e-4).has_value());
}

TEST(ShiTomasi, PatchExtractionAndBadInput)
{
	const cv::Mat im = sceneWithTextureAt({200, 100});
	const cv::Mat p = extractPatch(im, {200.4, 99.6}, 13);
	EXPECT_EQ(p.size(), cv::Size(13, 13));
	EXPECT_EQ(p.at<uchar>(6, 6), im.at<uchar>(100, 200));
	EXPECT_THROW(extractPatch(im, {3, 100}, 13), VisionError);
	EXPECT_THROW(bestCornerInBox(im, cv::Rect(0, 0, 10, 10), 12, 0), VisionError);
	cv::Mat f32;
	im.convertTo(f32, CV_32F);
	EXPECT_THROW(bestCornerInBox(f32, cv::Rect(0, 0, 10, 10), 13, 0), VisionError);
}
