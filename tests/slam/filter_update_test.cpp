// Updates of ActiveSlamFilter: gating, symmetry, and agreement of the three update methods.
#include <mrolr/slam/ActiveSlamFilter.h>

#include "slam_test_util.h"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>

#include <random>

using namespace mrolr::slam;

namespace
{
const mrolr::base::LabmateModel kModel{};
const HeadConstants kHead{0.25, 1.0};
const std::vector<Eigen::Vector3d> kPoints{{1, 2, 4}, {-1.5, 1.4, 3}, {0.3, 2.5, 5}, {2, 0.8, 2}};

/** A filter with kPoints initialised from exact measurements at the origin. */
ActiveSlamFilter makeFilter(UpdateMethod m)
{
	ActiveSlamFilter f(slamtest::defaultOptions(m), kModel);
	for (size_t i = 0; i < kPoints.size(); ++i)
		f.initialiseFeature("p" + std::to_string(i),
		                    predictMeasurement(Eigen::Vector3d::Zero(), kPoints[i], kHead));
	return f;
}

/** A fixed pseudo-random sequence of controls and noisy measurements, same for every method. */
void runSequence(ActiveSlamFilter& f, bool switchFeatures, bool twoFeatures = false)
{
	std::mt19937 rng(21);
	std::normal_distribution<double> n(0, 1);
	Eigen::Vector3d truth = Eigen::Vector3d::Zero();
	for (int k = 0; k < 30; ++k)
	{
		const mrolr::base::WheelControl u{0.1 + 0.01 * (k % 3), 0.1, 1.0};
		truth = kModel.move(truth, u);
		f.predict(u);
		const size_t i = switchFeatures ? static_cast<size_t>((k / 5) % 4) : 0;
		Eigen::Vector3d h = predictMeasurement(truth, kPoints[i], kHead);
		h += Eigen::Vector3d(0.002 * n(rng), 0.01 * n(rng), 0.002 * n(rng));
		std::vector<Observation> z{Observation{i, h}};
		const size_t i2 = (i + 1) % kPoints.size();
		if (twoFeatures)
			z.push_back({i2, predictMeasurement(truth, kPoints[i2], kHead) +
			                     Eigen::Vector3d(0.002 * n(rng), 0.01 * n(rng), 0.002 * n(rng))});
		f.update(z);
	}
}
}  // namespace

TEST(FilterUpdate, GateRejectsOutliersAndKeepsInliers)
{
	ActiveSlamFilter f = makeFilter(UpdateMethod::Sequential);
	f.predict({0.1, 0.1, 2});
	const Eigen::Vector3d good = f.predictedMeasurement(0) + Eigen::Vector3d(0.001, 0.005, 0.0);
	const Eigen::Vector3d bad = f.predictedMeasurement(1) + Eigen::Vector3d(0.3, 0, 0);
	const Eigen::VectorXd before = f.stateVector();
	const auto r = f.update({Observation{0, good}, Observation{1, bad}});
	ASSERT_EQ(r.accepted.size(), 1u);
	ASSERT_EQ(r.rejected.size(), 1u);
	EXPECT_EQ(r.rejected[0], 1u);
	EXPECT_LT(r.nis[0], f.gateThreshold());
	EXPECT_GT((f.stateVector() - before).norm(), 0);
	// An outlier alone changes nothing.
	const Eigen::VectorXd mid = f.stateVector();
	const auto r2 =
	    f.update({Observation{2, f.predictedMeasurement(2) + Eigen::Vector3d(0, 0.5, 0)}});
	EXPECT_EQ(r2.rejected.size(), 1u);
	EXPECT_EQ((f.stateVector() - mid).norm(), 0.0);
	EXPECT_NEAR(f.gateThreshold(), 11.3449, 1e-3);  // χ²₃ at 99 %
}

TEST(FilterUpdate, CovarianceStaysSymmetricPositiveSemiDefinite)
{
	for (auto m : {UpdateMethod::Sequential, UpdateMethod::Batch, UpdateMethod::Postponed})
	{
		ActiveSlamFilter f = makeFilter(m);
		runSequence(f, true);
		const Eigen::MatrixXd P = f.covariance();
		EXPECT_EQ((P - P.transpose()).cwiseAbs().maxCoeff(), 0.0) << toString(m);
		Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> e(P);
		EXPECT_GT(e.eigenvalues().minCoeff(), -1e-12 * e.eigenvalues().maxCoeff()) << toString(m);
	}
}

TEST(FilterUpdate, PostponedEqualsTheBatchUpdate)
{
	ActiveSlamFilter batch = makeFilter(UpdateMethod::Batch);
	ActiveSlamFilter postponed = makeFilter(UpdateMethod::Postponed);
	runSequence(batch, true);
	runSequence(postponed, true);
	const Eigen::MatrixXd Pb = batch.covariance(), Pp = postponed.covariance();
	EXPECT_LT((batch.stateVector() - postponed.stateVector()).norm() / batch.stateVector().norm(),
	          1e-9);
	EXPECT_LT((Pb - Pp).norm() / Pb.norm(), 1e-9);
}

TEST(FilterUpdate, SequentialEqualsTheBatchUpdate)
{
	// Linearised once per observation, the scalar updates with innovations corrected for the
	// earlier components are the batch update (MRPT 2.5's kfEKFAlaDavison is not: it keeps the
	// stale innovations and over-corrects; docs/slam.md). Also with several features per update.
	for (bool several : {false, true})
	{
		ActiveSlamFilter seq = makeFilter(UpdateMethod::Sequential);
		ActiveSlamFilter batch = makeFilter(UpdateMethod::Batch);
		runSequence(seq, true, several);
		runSequence(batch, true, several);
		const Eigen::MatrixXd Ps = seq.covariance(), Pb = batch.covariance();
		EXPECT_LT((seq.stateVector() - batch.stateVector()).norm() / batch.stateVector().norm(),
		          1e-9)
		    << several;
		EXPECT_LT((Ps - Pb).norm() / Pb.norm(), 1e-9) << several;
	}
}

TEST(FilterUpdate, PostponedReadsVehicleWithoutCatchUp)
{
	ActiveSlamFilter f = makeFilter(UpdateMethod::Postponed);
	f.predict({0.1, 0.1, 1});
	f.update({Observation{0, f.predictedMeasurement(0)}});
	const Eigen::Vector3d v = f.vehicle();
	EXPECT_TRUE(v.allFinite());
	EXPECT_THROW(f.update({Observation{9, v}}), std::out_of_range);
	EXPECT_THROW(f.update({Observation{0, v}, Observation{0, v}}), std::invalid_argument);
}

TEST(FilterUpdate, ProcessNoiseFloorAddsPerSecond)
{
	SlamOptions o = slamtest::defaultOptions();
	ActiveSlamFilter plain(o, kModel);
	o.process_noise_floor_m = 0.01;
	o.process_noise_floor_rad = 0.002;
	ActiveSlamFilter floored(o, kModel);
	const mrolr::base::WheelControl u{0.1, 0.1, 2.0};
	plain.predict(u);
	floored.predict(u);
	const Eigen::Matrix3d d = floored.vehicleCovariance() - plain.vehicleCovariance();
	EXPECT_NEAR(d(0, 0), 2.0 * 1e-4, 1e-15);
	EXPECT_NEAR(d(1, 1), 2.0 * 1e-4, 1e-15);
	EXPECT_NEAR(d(2, 2), 2.0 * 4e-6, 1e-15);
	EXPECT_NEAR(d(0, 1), 0, 1e-18);
}
