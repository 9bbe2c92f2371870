// Initialisation (5.46–5.48), deletion (5.49), zeroing (5.50–5.52) and known features (5.6.2) on
// small hand-built cases.
#include <mrolr/slam/ActiveSlamFilter.h>

#include "slam_test_util.h"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>

using namespace mrolr::slam;

namespace
{
const mrolr::base::LabmateModel kModel{};

Eigen::Matrix3d spd(double a, double b, double c)
{
	Eigen::Matrix3d M;
	M << a, 0.1 * a, 0, 0.1 * a, b, 0.01, 0, 0.01, c;
	return M;
}
}  // namespace

TEST(FilterMap, InitialisationFollowsEq548)
{
	ActiveSlamFilter f(slamtest::defaultOptions(), kModel);
	const Eigen::Vector3d xv(0.5, -0.2, 0.3);
	f.reset(xv);
	f.setState(xv, spd(0.01, 0.02, 0.003));
	const Eigen::Vector3d h(0.2, 0.3, 0.05);
	const size_t i = f.initialiseFeature("a", h);
	EXPECT_EQ(i, 0u);
	const auto g = initialiseFromMeasurement(xv, h, f.options().head.constants);
	const Eigen::MatrixXd P = f.covariance();
	const Eigen::Matrix3d Pvv = spd(0.01, 0.02, 0.003);
	EXPECT_LT((f.feature(0) - g.p_FinW).norm(), 1e-12);
	EXPECT_LT((P.block<3, 3>(3, 0) - g.dy_dxv * Pvv).norm(), 1e-15);
	const Eigen::Matrix3d Pyy = g.dy_dxv * Pvv * g.dy_dxv.transpose() +
	                            g.dy_dh * f.measurementNoise() * g.dy_dh.transpose();
	EXPECT_LT((P.block<3, 3>(3, 3) - Pyy).norm(), 1e-14);
	// A second feature is correlated with the first through the vehicle.
	f.initialiseFeature("b", {-0.4, 0.1, 0.04});
	const auto g2 = initialiseFromMeasurement(xv, {-0.4, 0.1, 0.04}, f.options().head.constants);
	EXPECT_LT((f.covariance().block<3, 3>(6, 3) - g2.dy_dxv * P.block<3, 3>(0, 3)).norm(), 1e-15);
}

TEST(FilterMap, DeletionRemovesRowsAndColumns)
{
	ActiveSlamFilter f(slamtest::defaultOptions(), kModel);
	f.addKnownFeature("k0", {1, 2, 3});
	f.addKnownFeature("k1", {2, 2, 3});
	f.addKnownFeature("k2", {3, 2, 3});
	Eigen::MatrixXd A = Eigen::MatrixXd::Random(12, 12);
	const Eigen::MatrixXd P = A * A.transpose();
	Eigen::VectorXd x = Eigen::VectorXd::LinSpaced(12, 0, 11);
	f.setState(x, P);
	f.deleteFeature(1);
	ASSERT_EQ(f.numFeatures(), 2u);
	EXPECT_EQ(f.info(1).label, "k2");
	const std::vector<int> keep{0, 1, 2, 3, 4, 5, 9, 10, 11};
	const Eigen::MatrixXd Pk = P(keep, keep);
	EXPECT_EQ((f.covariance() - Pk).norm(), 0.0);
	EXPECT_EQ((f.stateVector() - x(keep)).norm(), 0.0);
	EXPECT_THROW(f.deleteFeature(2), std::out_of_range);
}

TEST(FilterMap, ZeroingMakesTheVehicleTheOrigin)
{
	ActiveSlamFilter f(slamtest::defaultOptions(), kModel);
	const Eigen::Vector3d xv(1.0, 2.0, M_PI / 2);  // at z = 1, x = 2 facing +x
	f.reset(xv);
	f.addKnownFeature("ahead", {5, 1.5, 1});  // 3 m ahead, 0.5 m above the ground... in W
	f.initialiseFeature("new", {0.3, 0.1, 0.04});
	const Eigen::Vector3d y1 = f.feature(1);
	f.zeroWorldFrame();
	EXPECT_EQ(f.vehicle().norm(), 0.0);
	EXPECT_EQ(f.vehicleCovariance().norm(), 0.0);
	// In the new frame the first feature lies 3 m straight ahead (z), same height above ground.
	EXPECT_LT((f.feature(0) - Eigen::Vector3d(0, 1.5, 3)).norm(), 1e-12);
	// Measurements are unchanged by a change of world frame.
	const auto& head = f.options().head.constants;
	EXPECT_LT((predictMeasurement(Eigen::Vector3d::Zero(), f.feature(1), head) -
	           predictMeasurement(xv, y1, head))
	              .norm(),
	          1e-12);
	// With the vehicle known exactly, feature covariances just rotate: same eigenvalues.
	Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> e(f.featureCovariance(1));
	EXPECT_GT(e.eigenvalues().minCoeff(), 0);
	EXPECT_EQ(f.featureCovariance(0).norm(), 0.0);
}

TEST(FilterMap, KnownFeaturesKeepZeroCovariance)
{
	for (auto m : {UpdateMethod::Sequential, UpdateMethod::Batch, UpdateMethod::Postponed})
	{
		ActiveSlamFilter f(slamtest::defaultOptions(m), kModel);
		f.addKnownFeature("k", {0.5, 1.8, 4});
		f.initialiseFeature("n",
		                    predictMeasurement(Eigen::Vector3d::Zero(), {-1, 1.2, 3}, {0.25, 1}));
		for (int k = 0; k < 10; ++k)
		{
			f.predict({0.1, 0.1, 1});
			const Eigen::Vector3d h = predictMeasurement(f.vehicle(), {0.5, 1.8, 4}, {0.25, 1});
			f.update({Observation{0, h}});
			if (k % 3 == 0) f.update({Observation{1, f.predictedMeasurement(1)}});
		}
		const Eigen::MatrixXd P = f.covariance();
		EXPECT_EQ(P.block(3, 0, 3, P.cols()).norm(), 0.0) << toString(m);
		EXPECT_GT((P.block<3, 3>(0, 0).trace()), 0) << toString(m);
		EXPECT_EQ((P - P.transpose()).norm(), 0.0);
	}
}

TEST(FilterMap, DeletionRuleNeedsMoreThanHalfOfTheLastTenFailed)
{
	ActiveSlamFilter f(slamtest::defaultOptions(), kModel);
	f.addKnownFeature("k", {0, 1, 3});
	for (int k = 0; k < 5; ++k) f.recordAttempt(0, true);
	for (int k = 0; k < 5; ++k) f.recordAttempt(0, false);
	EXPECT_FALSE(f.shouldDelete(0));  // 5 of 10: not more than half
	f.recordAttempt(0, false);        // the oldest success leaves the window: 6 of 10
	EXPECT_TRUE(f.shouldDelete(0));   // 6 failures in the last 10
}
