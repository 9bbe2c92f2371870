// Measuring a mapped feature in the ellipses its innovation covariance projects (thesis 5.5.4):
// the measured ideal-head angles agree with the truth to well within R of eq 5.41.
#include "TestScene.h"

#include <mrolr/geometry/IdealHead.h>
#include <mrolr/vision/FeatureMeasurement.h>
#include <mrolr/vision/ShiTomasi.h>

#include <gtest/gtest.h>

using namespace mrolr;
using namespace mrolr::vision;

TEST(FeatureMeasurement, MeasuresTheTrueAnglesFromAnOffsetPrediction)
{
	const auto head = test::configuredHead();
	const auto options = test::configuredVision();
	SyntheticStereoHead device(head, 2.0, 31);
	const Eigen::Vector3d p(-0.4, 0.3, 2.8);
	device.setPoints(test::texturedPoints({p, {0.5, 0.0, 2.0}}));
	device.moveTo(head.fixate(p));
	const cv::Mat patch = extractPatch(device.grab().left, {320, 240}, 13);
	const double I = head.options().interocular_m;
	const Eigen::Vector3d h_true = geometry::idealHeadMeasure(p, I);
	const Eigen::Matrix3d S = Eigen::Vector3d(1e-4, 1e-4, 2e-5).asDiagonal();
	const Eigen::Vector3d h_pred = h_true + Eigen::Vector3d(0.008, -0.006, 0.002);  // ~2 sigma off
	const FeatureMeasurement m = measureWithHead(device, head, patch, h_pred, S, options);
	ASSERT_TRUE(m.found);
	EXPECT_TRUE(m.ellipse_left.contains(m.left.uv));
	EXPECT_TRUE(m.ellipse_right.contains(m.right.uv));
	EXPECT_LT(std::abs(m.h[0] - h_true[0]), 1e-3);  // pan, rad (R: 2e-3 rad sigma)
	EXPECT_LT(std::abs(m.h[1] - h_true[1]), 1e-3);
	EXPECT_LT(std::abs(m.h[2] - h_true[2]), 2e-3);
	// the same prediction with a tiny covariance: the ellipse misses the feature
	const FeatureMeasurement tight =
	    measureWithHead(device, head, patch, h_pred, S * 1e-4, options);
	EXPECT_FALSE(tight.found);
}

TEST(FeatureMeasurement, PredictionBeyondTheJointLimitsIsNotFound)
{
	const auto head = test::configuredHead();
	SyntheticStereoHead device(head, 2.0, 32);
	const Eigen::Vector3d h_behind(3.0, 0.0, 0.05);  // pan 172 deg
	const FeatureMeasurement m =
	    measureWithHead(device, head, makeTexture(13, 1), h_behind,
	                    Eigen::Matrix3d::Identity() * 1e-4, test::configuredVision());
	EXPECT_FALSE(m.found);
}
