// Dense edge stereo (stereo/DenseEdgeStereo.h): edgels the edge matcher leaves unmatched take the
// SGBM disparity of their nearer side. Synthetic rectified pairs with known disparities: a
// textured background at disparity 50 px and a textured square in front at 80 px, so the square's
// outline is an occluding edge (its foreground is the square) and a dark stroke on the square is
// a mark whose two sides agree.
#include "SyntheticStereo.h"

#include <mrolr/stereo/DenseEdgeStereo.h>
#include <mrolr/stereo/Rectifier.h>

#include <gtest/gtest.h>

#include <opencv2/imgproc.hpp>

using namespace mrolr::stereo;
using namespace mrolr::stereo::test;

namespace
{
constexpr int kW = 640, kH = 480;
constexpr int kBackD = 50, kFrontD = 80;
const cv::Rect kSquare(260, 180, 160, 120);  // in the left image
const cv::Rect kStroke(300, 236, 80, 6);     // dark stroke on the square (left image)

/** Smooth random texture (blurred noise), mean @p mean, ± about 25 grey. */
cv::Mat texture(int seed, int mean)
{
	cv::RNG rng(seed);
	cv::Mat n(kH, kW, CV_32F);
	rng.fill(n, cv::RNG::NORMAL, 0, 60);
	cv::GaussianBlur(n, n, {0, 0}, 1.2);
	cv::Mat out;
	n.convertTo(out, CV_8U, 1, mean);
	return out;
}

/** Rectified left and right images: each right pixel x shows the left pixel x + d. */
void renderRectified(cv::Mat& left, cv::Mat& right)
{
	const cv::Mat back = texture(1, 70), front = texture(2, 170);
	left = back.clone();
	front(kSquare).copyTo(left(kSquare));
	left(kStroke).setTo(20);
	right.create(kH, kW, CV_8U);
	for (int y = 0; y < kH; ++y)
		for (int x = 0; x < kW; ++x)
		{
			const int xf = x + kFrontD, xb = x + kBackD;  // left columns seen at right column x
			if (xf < kW && kSquare.contains({xf, y}))
				right.at<uchar>(y, x) = left.at<uchar>(y, xf);
			else
				right.at<uchar>(y, x) = xb < kW ? back.at<uchar>(y, xb) : 70;
		}
}

/** Edgels along a row from x0 to x1 (px), gradient along +y or −y. */
EdgeString rowEdge(double y, int x0, int x1, double grad_y)
{
	EdgeString s;
	for (int x = x0; x <= x1; ++x) s.push_back({{double(x), y}, {0, grad_y}});
	return s;
}

DenseEdgeOptions options()
{
	DenseEdgeOptions o;
	o.enabled = true;
	return o;
}

cv::Mat disparity()
{
	cv::Mat l, r;
	renderRectified(l, r);
	return denseDisparity(l, r, 30, 110, options());
}

double median(std::vector<double> v)
{
	std::nth_element(v.begin(), v.begin() + long(v.size() / 2), v.end());
	return v[v.size() / 2];
}
}  // namespace

TEST(DenseEdgeStereo, SgbmFindsBothSurfaces)
{
	const cv::Mat d = disparity();
	EXPECT_NEAR(d.at<float>(240, 280), kFrontD, 0.5);  // on the square, off the stroke
	EXPECT_NEAR(d.at<float>(100, 300), kBackD, 0.5);
}

TEST(DenseEdgeStereo, OccludingEdgeTakesTheNearerSide)
{
	const cv::Mat d = disparity();
	const auto o = options();
	// top edge of the square: along the scanlines, the square below (+y) is in front
	std::vector<double> top, farther;
	for (const auto& e : rowEdge(kSquare.y - 0.5, kSquare.x + 10, kSquare.br().x - 10, 1))
	{
		top.push_back(edgelDisparity(e, d, o));
		// the far side alone (what a "farther side" rule would give) differs: the check can fail
		farther.push_back(d.at<float>(cvRound(e.p.y - 3), cvRound(e.p.x)));
	}
	EXPECT_NEAR(median(top), kFrontD, 0.5);
	EXPECT_NEAR(median(farther), kBackD, 1.0);
}

TEST(DenseEdgeStereo, MarkOnASurfaceTakesItsDisparity)
{
	const cv::Mat d = disparity();
	std::vector<double> v;
	for (const auto& e : rowEdge(kStroke.y - 0.5, kStroke.x + 5, kStroke.br().x - 5, 1))
		v.push_back(edgelDisparity(e, d, options()));
	EXPECT_NEAR(median(v), kFrontD, 0.5);
}

TEST(DenseEdgeStereo, UnmatchedEdgelsBecome3DStringsAtTheirDepth)
{
	const cv::Mat d = disparity();
	const auto rig = testRig(0);  // identical parallel cameras: rectification is the identity
	const Rectifier rect(rig);
	ASSERT_NEAR(rect.disparityOffset_px(), 0, 1e-6);
	const std::vector<EdgeString> left = {
	    rowEdge(kSquare.y - 0.5, kSquare.x + 10, kSquare.br().x - 10, 1),
	    rowEdge(kSquare.br().y - 0.5, kSquare.x + 10, kSquare.br().x - 10, -1)};
	// the first 40 edgels of the top edge are matched (at a wrong disparity, so that using them
	// would show): with unmatched_only they are left out, the rest comes from the dense map
	std::vector<EdgeMatch> matches;
	for (int i = 0; i < 40; ++i)
		matches.push_back({0, i, left[0][i].p.x, left[0][i].p.y, 60, 1});
	auto o = options();
	const auto strings = denseEdgeStrings(left, matches, d, rect, o);
	ASSERT_EQ(strings.size(), 2u);
	EXPECT_EQ(strings[0].size(), left[0].size() - 40);
	EXPECT_EQ(strings[1].size(), left[1].size());
	const double z = rect.focal_px() * rig.baseline_mm() / kFrontD;
	for (const auto& s : strings)
	{
		std::vector<double> zs;
		for (const auto& e : s) zs.push_back(e.p_L_mm.z());
		EXPECT_NEAR(median(zs), z, 0.01 * z);
	}
	o.unmatched_only = false;  // the matched edgels join with their own disparity: a jump
	const auto joined = denseEdgeStrings(left, matches, d, rect, o);
	ASSERT_EQ(joined.size(), 3u);
	EXPECT_EQ(joined[0].size(), 40u);
	EXPECT_NEAR(joined[0].front().d_px, 60, 1e-9);
}

TEST(DenseEdgeStereo, EdgelsWithoutDisparityBreakTheRun)
{
	const cv::Mat d = disparity();
	cv::Mat holes = d.clone();
	holes(cv::Rect(330, 0, 20, kH)).setTo(std::numeric_limits<float>::quiet_NaN());
	const auto rig = testRig(0);
	const Rectifier rect(rig);
	const std::vector<EdgeString> left = {
	    rowEdge(kSquare.y - 0.5, kSquare.x + 10, kSquare.br().x - 10, 1)};
	EXPECT_EQ(denseEdgeStrings(left, {}, d, rect, options()).size(), 1u);
	const auto broken = denseEdgeStrings(left, {}, holes, rect, options());
	ASSERT_EQ(broken.size(), 2u);
	for (const auto& s : broken)
		for (const auto& e : s) EXPECT_TRUE(e.xy_px.x < 330 || e.xy_px.x >= 350);
}
