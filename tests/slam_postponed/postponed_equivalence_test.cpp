// The postponed update (thesis appendix C) against a plain full EKF over long random runs with the
// real Labmate motion model and ideal-head measurements, switching the tracked feature every 1–8
// steps.

#include "Lockstep.h"

#include <mrpt/math/CMatrixDynamic.h>
#include <mrpt/math/CVectorDynamic.h>

#include <gtest/gtest.h>
#include <Eigen/Eigenvalues>

#include <iostream>
#include <tuple>

using mrolr::slam::PostponedTracker33;
using mrolr::slam::test::Lockstep;
using mrolr::slam::test::relativeError;
using mrolr::slam::test::ScenarioOptions;
using mrolr::slam::test::scenarioOf;

namespace
{
constexpr double kTolerance = 1e-9;  // relative, required by issue 3
constexpr int kSteps = 400;

// (N features, seed, sequential scalar updates)
class PostponedEquivalence : public ::testing::TestWithParam<std::tuple<int, unsigned, bool>>
{
};

TEST_P(PostponedEquivalence, MatchesFullEkfOverLongRunWithSwitches)
{
	const auto [N, seed, scalar] = GetParam();
	Lockstep run(scenarioOf(N, seed), scalar);
	run.run(kSteps);
	const auto& e = run.errors();
	std::cout << "N=" << N << " switches=" << e.switches << " max relative error: x " << e.state
	          << ", P " << e.covariance << ", active " << e.active << "\n";
	EXPECT_GE(e.switches, kSteps / 8) << "the run must switch features often";
	EXPECT_LT(e.state, kTolerance);
	EXPECT_LT(e.covariance, kTolerance);
	EXPECT_LT(e.active, kTolerance);
	EXPECT_EQ(e.asymmetry, 0.0) << "catch-up must leave P exactly symmetric";
}

TEST_P(PostponedEquivalence, CovarianceIsPositiveSemiDefiniteAfterCatchUp)
{
	const auto [N, seed, scalar] = GetParam();
	Lockstep run(scenarioOf(N, seed), scalar);
	run.run(kSteps);
	const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(run.trackerCovariance());
	const Eigen::VectorXd lambda = eig.eigenvalues();
	EXPECT_GE(lambda.minCoeff(), -1e-12 * lambda.maxCoeff());
	EXPECT_GT(lambda.maxCoeff(), 0.0);
}

INSTANTIATE_TEST_SUITE_P(RandomRuns, PostponedEquivalence,
                         ::testing::Combine(::testing::Values(1, 5, 12, 30),
                                            ::testing::Values(7u, 2024u), ::testing::Bool()));

// Above 42 features the catch-up works on several 128-wide blocks of P.
TEST(PostponedTracker, MatchesFullEkfWithManyFeatures)
{
	for (bool scalar : {false, true})
	{
		Lockstep run(scenarioOf(60, 99), scalar);
		run.run(150);
		EXPECT_LT(run.errors().state, kTolerance);
		EXPECT_LT(run.errors().covariance, kTolerance);
		EXPECT_EQ(run.errors().asymmetry, 0.0);
	}
}

TEST(PostponedTracker, BlockedSymmetricUpdateEqualsPlainProduct)
{
	for (int n : {5, 128, 301})
	{
		const Eigen::MatrixXd B = Eigen::MatrixXd::Random(n, n);
		Eigen::MatrixXd P = B + B.transpose();
		const Eigen::MatrixXd W = Eigen::MatrixXd::Random(n, 6);
		Eigen::MatrixXd Psi = Eigen::MatrixXd::Random(6, 6);
		Psi = (Psi + Psi.transpose()).eval();
		const Eigen::MatrixXd expected = P - W * Psi * W.transpose();
		mrolr::slam::detail::subtractSymmetricProduct(P, (W * Psi).eval(), W);
		EXPECT_LT(relativeError(P, expected), 1e-14) << "n = " << n;
		EXPECT_EQ(P, P.transpose()) << "n = " << n;
	}
}

// The comparison has teeth: before catch-up the stored blocks are stale, far beyond the tolerance.
TEST(PostponedTracker, StaleBlocksDifferBeforeCatchUp)
{
	Lockstep run(scenarioOf(10, 3), false);
	for (int k = 0; k < 5; ++k) run.step();
	EXPECT_GT(relativeError(run.trackerCovariance(), run.reference().P), 1e-4);
	run.catchUpAndCompare();
	EXPECT_LT(run.errors().covariance, kTolerance);
	EXPECT_LT(run.errors().state, kTolerance);
}

TEST(PostponedTracker, CatchUpWithoutStepsLeavesStateUntouched)
{
	Lockstep run(scenarioOf(6, 11), false);
	run.run(30);
	const Eigen::VectorXd x = run.trackerState();
	const Eigen::MatrixXd P = run.trackerCovariance();
	run.catchUpAndCompare();
	EXPECT_EQ(run.trackerState(), x);
	EXPECT_EQ(run.trackerCovariance(), P);
}

// MRPT's CKalmanFilterCapable stores P as a row-major CMatrixDynamic: the tracker works on its
// Eigen map in place and gives the same result as on a column-major Eigen matrix.
TEST(PostponedTracker, WorksInPlaceOnMrptRowMajorStorage)
{
	const int n = 3 + 3 * 8;
	Eigen::MatrixXd B = Eigen::MatrixXd::Random(n, n);
	Eigen::MatrixXd P = B * B.transpose() / n + Eigen::MatrixXd::Identity(n, n);
	Eigen::VectorXd x = Eigen::VectorXd::Random(n);
	mrpt::math::CMatrixDynamic<double> Pm(P);
	mrpt::math::CVectorDynamic<double> xm(x);
	auto Pmap = Pm.asEigen();
	auto xmap = xm.asEigen();
	PostponedTracker33 a, b;
	a.start(x, P, 4);
	b.start(xmap, Pmap, 4);
	Eigen::Matrix<double, 3, 6> H = Eigen::Matrix<double, 3, 6>::Random();
	for (PostponedTracker33* t : {&a, &b})
	{
		t->predict(Eigen::Vector3d(0.1, 0.2, 0.3), Eigen::Matrix3d::Identity() * 1.01,
		           Eigen::Matrix3d::Identity() * 1e-3);
		t->update<3>(Eigen::Vector3d(0.01, -0.02, 0.005), H, Eigen::Matrix3d::Identity() * 1e-2);
	}
	a.catchUp(x, P);
	b.catchUp(xmap, Pmap);
	EXPECT_LT(relativeError(Pmap, P), 1e-14);
	EXPECT_LT(relativeError(xmap, x), 1e-14);
	EXPECT_EQ(Pmap, Pmap.transpose());
}

}  // namespace
