// Epipolar search (thesis 5.3): the band of a left pixel holds the true right image of the point
// for random head angles, and matching along it ignores an identical decoy off the band.
#include "TestScene.h"

#include <mrolr/vision/PatchSearch.h>
#include <mrolr/vision/SearchRegion.h>
#include <mrolr/vision/ShiTomasi.h>

#include <gtest/gtest.h>

#include <random>

using namespace mrolr;
using namespace mrolr::vision;

TEST(Epipolar, BandHoldsTheTrueRightProjection)
{
	const auto head = test::configuredHead();
	std::mt19937 rng(5);
	std::uniform_real_distribution<double> ang(-0.3, 0.3), verg(0.0, 0.1), xy(-1, 1), depth(0.8, 8);
	for (int k = 0; k < 200; ++k)
	{
		const geometry::HeadAngles a{ang(rng), ang(rng), -verg(rng), verg(rng)};
		const Eigen::Vector3d p_L = depth(rng) * Eigen::Vector3d(0.3 * xy(rng), 0.2 * xy(rng), 1);
		const Eigen::Vector3d p = head.T_LinC0(a) * p_L;
		const auto px = head.project(p, a);
		const EpipolarBand band = epipolarBand(head, a, {px.uL, px.vL}, 0.3, 30, 7);
		EXPECT_LT(band.distance({px.uR, px.vR}), 1e-6) << "trial " << k;
		EXPECT_GT(band.distance({px.uR, px.vR + 8}), 0.5);
	}
}

TEST(Epipolar, MatchingAlongTheBandFindsTheRightPointNotTheDecoy)
{
	const auto head = test::configuredHead();
	SyntheticStereoHead device(head, 2.0, 9);
	const Eigen::Vector3d p(0.2, 0.1, 2.5);
	const geometry::HeadAngles a{0.05, 0.02, -0.04, 0.04};
	const auto truth = head.project(p, a);
	device.setPoints(test::texturedPoints({p}));
	device.moveTo(a);
	StereoImages im = device.grab();
	const cv::Mat patch = extractPatch(im.left, {truth.uL, truth.vL}, 13);
	// the same texture pasted 25 px below the true right image: identical, but off the band
	cv::Mat tex = device.points()[0].texture;
	const int du = int(std::lround(truth.uR)) - 15, dv = int(std::lround(truth.vR)) + 25 - 15;
	tex.copyTo(im.right(cv::Rect(du, dv, 31, 31)));
	const EpipolarBand band = epipolarBand(head, a, {truth.uL, truth.vL}, 0.3, 30, 7);
	const PatchMatch m = searchEpipolar(im.right, patch, band, 0.9);
	ASSERT_TRUE(m.found) << m.score;
	EXPECT_NEAR(m.uv.x(), truth.uR, 1.0);
	EXPECT_NEAR(m.uv.y(), truth.vR, 1.0);
	const auto tri = head.triangulatePoint({truth.uL, truth.vL, m.uv.x(), m.uv.y()}, a);
	EXPECT_LT((tri - p).norm(), 0.05 * p.norm());
}
