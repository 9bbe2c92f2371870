#include <mrolr/slam/Chi2.h>
#include <mrolr/slam/FeatureSelection.h>
#include <mrolr/slam/FeatureVisibility.h>

#include "slam_test_util.h"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>

using namespace mrolr::slam;

TEST(FeatureSelection, VolumeIsTheEllipsoidVolume)
{
	Eigen::Matrix3d A = Eigen::Matrix3d::Random();
	const Eigen::Matrix3d S = A * A.transpose() + 0.1 * Eigen::Matrix3d::Identity();
	Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> e(S);
	const auto l = e.eigenvalues();
	const double expected =
	    4.0 / 3.0 * M_PI * 27 * std::sqrt(l[0]) * std::sqrt(l[1]) * std::sqrt(l[2]);
	EXPECT_NEAR(innovationVolume(S, 3), expected, 1e-12 * expected);
}

TEST(FeatureSelection, LargestVolumePicksTheLeastCertainFeature)
{
	const SlamOptions o = slamtest::defaultOptions();
	Eigen::VectorXd x(9);
	x << 0, 0, 0, 1, 1.5, 3, -1, 1.5, 3;
	Eigen::MatrixXd P = Eigen::MatrixXd::Zero(9, 9);
	P.block<3, 3>(3, 3) = 0.01 * Eigen::Matrix3d::Identity();
	P.block<3, 3>(6, 6) = 0.04 * Eigen::Matrix3d::Identity();
	EXPECT_EQ(*largestVolume(x, P, {0, 1}, o), 1u);
	EXPECT_EQ(*largestVolume(x, P, {0}, o), 0u);
	EXPECT_FALSE(largestVolume(x, P, {}, o).has_value());
}

TEST(FeatureSelection, SaccadeCostGrowsWithTheHeadMove)
{
	SlamOptions o = slamtest::defaultOptions();
	o.head_speed_deg_per_s = 30;
	o.saccade_overhead_s = 0.5;
	o.step_time_s = 1;
	EXPECT_EQ(measurementsLostBySaccade({0, 0, 0.05}, {0, 0, 0.05}, o), 1);
	EXPECT_EQ(measurementsLostBySaccade({0, 0, 0.05}, {M_PI / 2, 0, 0.05}, o), 4);  // 3 s + 0.5 s
}

TEST(FeatureSelection, SaccadeDecisionStaysOrSwitches)
{
	SlamOptions o = slamtest::defaultOptions();
	const mrolr::base::LabmateModel model;
	SaccadeQuery q;
	q.x.resize(9);
	q.x << 0, 0, 0, 1, 1.5, 3, -1, 1.5, 3;
	q.P = Eigen::MatrixXd::Zero(9, 9);
	q.P.topLeftCorner<3, 3>() = 1e-3 * Eigen::Matrix3d::Identity();
	q.P.block<3, 3>(3, 3) = 1e-4 * Eigen::Matrix3d::Identity();
	q.P.block<3, 3>(6, 6) = 0.05 * Eigen::Matrix3d::Identity();  // feature 1 very uncertain
	q.visible = {0, 1};
	q.current = 0;
	q.head_angles =
	    predictMeasurement(Eigen::Vector3d::Zero(), q.x.segment<3>(3), o.head.constants);
	q.upcoming = {mrolr::base::WheelControl{0.1, 0.1, 2}};
	const auto d = decideSaccade(q, o, model);
	ASSERT_TRUE(d.feature.has_value());
	EXPECT_EQ(*d.feature, 1u);  // measuring the uncertain feature lowers Vs(max) most
	EXPECT_TRUE(d.saccade);
	EXPECT_EQ(d.vs_max.size(), 2u);
	// When both features are equally certain the current one is kept (no saccade cost).
	q.P.block<3, 3>(6, 6) = 1e-4 * Eigen::Matrix3d::Identity();
	const auto d2 = decideSaccade(q, o, model);
	EXPECT_EQ(*d2.feature, 0u);
	EXPECT_FALSE(d2.saccade);
}

TEST(FeatureVisibility, ViewpointRulesOf521)
{
	const SlamOptions o = slamtest::defaultOptions();
	const Eigen::Vector3d y(0, 1.5, 4);
	const Eigen::Vector3d c0(0, 1, 0);  // seen first from the origin
	EXPECT_EQ(assessVisibility({0, 0, 0}, y, c0, o), Visibility::Visible);
	EXPECT_EQ(assessVisibility({2.5, 0, 0}, y, c0, o), Visibility::DistanceRatio);  // 1.5 / 4
	EXPECT_EQ(assessVisibility({4, 4, -M_PI / 2}, y, c0, o), Visibility::ViewDirection);
	EXPECT_EQ(assessVisibility({0, 0, M_PI}, y, c0, o), Visibility::BeyondPanLimit);
	EXPECT_EQ(headCanFixate({0, 0, 0}, {0, 1.0, 0.1}, o.head), Visibility::BeyondVergenceLimit);
	EXPECT_EQ(headCanFixate({0, 0, 0}, {0, 5, 1}, o.head), Visibility::BeyondTiltLimit);
}

TEST(Chi2, QuantilesMatchTables)
{
	EXPECT_NEAR(chi2Quantile(0.99, 3), 11.344867, 1e-5);
	EXPECT_NEAR(chi2Quantile(0.95, 1), 3.841459, 1e-5);
	EXPECT_NEAR(chi2Quantile(0.025, 150), 117.98451, 1e-3);
	EXPECT_NEAR(chi2Quantile(0.975, 150), 185.80006, 1e-3);
	EXPECT_THROW(chi2Quantile(1.0, 3), std::invalid_argument);
}
