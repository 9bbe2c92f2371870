// The consistency options of ActiveSlamFilter: the second-order process noise against a Monte-Carlo
// of the motion model, first-estimate Jacobians (FEJ-EKF), and the optional [slam] keys.
#include <mrolr/slam/ActiveSlamFilter.h>
#include <mrolr/slam/ProcessNoise.h>
#include <mrolr/util/Config.h>

#include "slam_test_util.h"

#include <gtest/gtest.h>
#include <mrpt/config/CConfigFileMemory.h>

#include <Eigen/Eigenvalues>

#include <fstream>
#include <random>
#include <regex>
#include <sstream>

using namespace mrolr::slam;
using mrolr::base::WheelControl;

namespace
{
const mrolr::base::LabmateModel kModel{};
const HeadConstants kHead{0.25, 1.0};

/** Covariance of f(x_v, u + w), w ~ N(0, U), from n samples. */
Eigen::Matrix3d monteCarloQ(const Eigen::Vector3d& x_v, const WheelControl& u, int n)
{
	std::mt19937 rng(5);
	std::normal_distribution<double> g(0, 1);
	const Eigen::Matrix2d U = kModel.controlCovariance(u);
	const Eigen::Vector3d f0 = kModel.move(x_v, u);
	Eigen::Vector3d mean = Eigen::Vector3d::Zero();
	Eigen::Matrix3d M = Eigen::Matrix3d::Zero();
	for (int k = 0; k < n; ++k)
	{
		const WheelControl w{u.v1_mps + std::sqrt(U(0, 0)) * g(rng),
		                     u.v2_mps + std::sqrt(U(1, 1)) * g(rng), u.dt_s};
		const Eigen::Vector3d d = kModel.move(x_v, w) - f0;
		mean += d;
		M += d * d.transpose();
	}
	mean /= n;
	return M / n - mean * mean.transpose();
}

void expectSecondOrderFillsTheNullDirection(const WheelControl& u)
{
	const Eigen::Vector3d x_v(0.5, -0.2, 0.7);
	const Eigen::Matrix3d Q1 = kModel.processNoise(x_v, u);
	const Eigen::Matrix3d Q2 = secondOrderProcessNoise(kModel, x_v, u);
	const Eigen::Matrix3d C = monteCarloQ(x_v, u, 400000);
	// The first-order Q has rank 2: along its null direction only the second-order term is left.
	const Eigen::Vector3d n =
	    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(Q1).eigenvectors().col(0);
	const double mc = n.dot(C * n);
	EXPECT_LT(n.dot(Q1 * n), 1e-3 * mc);
	EXPECT_NEAR(n.dot((Q1 + Q2) * n), mc, 0.05 * mc);
	EXPECT_LT((Q1 + Q2 - C).norm(), 0.02 * C.norm());
}

ActiveSlamFilter filterWith(JacobianPoint j, UpdateMethod m)
{
	SlamOptions o = slamtest::defaultOptions(m);
	o.jacobians = j;
	ActiveSlamFilter f(o, kModel);
	f.initialiseFeature("a", predictMeasurement(Eigen::Vector3d::Zero(), {1, 2, 4}, kHead));
	f.initialiseFeature("b", predictMeasurement(Eigen::Vector3d::Zero(), {-1.5, 1.4, 3}, kHead));
	return f;
}

/** One prediction and one measurement of feature i (noise from rng). */
void stepAndMeasure(ActiveSlamFilter& f, Eigen::Vector3d& truth, size_t i, std::mt19937& rng)
{
	std::normal_distribution<double> n(0, 1);
	const WheelControl u{0.11, 0.1, 2.0};
	truth = kModel.move(truth, u);
	f.predict(u);
	const Eigen::Vector3d p[2] = {{1, 2, 4}, {-1.5, 1.4, 3}};
	Eigen::Vector3d h = predictMeasurement(truth, p[i], kHead);
	h += Eigen::Vector3d(0.002 * n(rng), 0.01 * n(rng), 0.002 * n(rng));
	f.update({Observation{i, h}});
}

std::string ekfSimIniWith(const std::string& from, const std::string& to)
{
	std::ifstream in(std::string(MROLR_SOURCE_DIR) + "/config/ekf_sim.ini");
	std::stringstream ss;
	ss << in.rdbuf();
	return std::regex_replace(ss.str(), std::regex(from), to);
}

SlamOptions loadSlam(const std::string& text)
{
	mrpt::config::CConfigFileMemory cfg(text);
	SlamOptions o;
	o.loadFromConfigFile(cfg, "slam");
	return o;
}
}  // namespace

TEST(ConsistencyOptions, SecondOrderProcessNoiseMatchesMonteCarloOnAStraightStep)
{
	expectSecondOrderFillsTheNullDirection({0.1, 0.1, 2.0});
}

TEST(ConsistencyOptions, SecondOrderProcessNoiseMatchesMonteCarloOnARotation)
{
	expectSecondOrderFillsTheNullDirection({0.05, -0.05, 9.4});
}

TEST(ConsistencyOptions, FirstEstimateEqualsStandardUntilTheEstimatesMove)
{
	ActiveSlamFilter std_f = filterWith(JacobianPoint::Standard, UpdateMethod::Sequential);
	ActiveSlamFilter fej = filterWith(JacobianPoint::FirstEstimate, UpdateMethod::Sequential);
	std::mt19937 r1(3), r2(3);
	Eigen::Vector3d t1 = Eigen::Vector3d::Zero(), t2 = t1;
	// First step: every linearisation point is still the first estimate.
	stepAndMeasure(std_f, t1, 0, r1);
	stepAndMeasure(fej, t2, 0, r2);
	EXPECT_LT((std_f.stateVector() - fej.stateVector()).norm(), 1e-12);
	EXPECT_LT((std_f.covariance() - fej.covariance()).norm(), 1e-15);
	for (int k = 0; k < 20; ++k)
	{
		stepAndMeasure(std_f, t1, static_cast<size_t>(k % 2), r1);
		stepAndMeasure(fej, t2, static_cast<size_t>(k % 2), r2);
	}
	const Eigen::MatrixXd P = fej.covariance();
	EXPECT_GT((std_f.covariance() - P).norm(), 1e-3 * P.norm());
	EXPECT_LT((std_f.vehicle() - fej.vehicle()).norm(), 0.05);
	EXPECT_LT((P - P.transpose()).norm(), 1e-15);
	EXPECT_GT(Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(P).eigenvalues().minCoeff(), -1e-12);
}

TEST(ConsistencyOptions, FirstEstimatePostponedEqualsFirstEstimateBatch)
{
	ActiveSlamFilter batch = filterWith(JacobianPoint::FirstEstimate, UpdateMethod::Batch);
	ActiveSlamFilter postponed = filterWith(JacobianPoint::FirstEstimate, UpdateMethod::Postponed);
	std::mt19937 r1(4), r2(4);
	Eigen::Vector3d t1 = Eigen::Vector3d::Zero(), t2 = t1;
	for (int k = 0; k < 24; ++k)
	{
		stepAndMeasure(batch, t1, static_cast<size_t>((k / 6) % 2), r1);
		stepAndMeasure(postponed, t2, static_cast<size_t>((k / 6) % 2), r2);
	}
	const Eigen::MatrixXd Pb = batch.covariance();
	EXPECT_LT((batch.stateVector() - postponed.stateVector()).norm(), 1e-9);
	EXPECT_LT((Pb - postponed.covariance()).norm() / Pb.norm(), 1e-9);
}

TEST(ConsistencyOptions, OptionalKeysHaveDefaultsAndBadValuesNameTheKey)
{
	const SlamOptions shipped = loadSlam(ekfSimIniWith("$^", ""));
	EXPECT_EQ(shipped.jacobians, JacobianPoint::FirstEstimate);
	EXPECT_EQ(shipped.process_noise_order, 2);
	const SlamOptions defaults =
	    loadSlam(ekfSimIniWith("\n(jacobians|process_noise_order) = [a-z_0-9]+", ""));
	EXPECT_EQ(defaults.jacobians, JacobianPoint::Standard);
	EXPECT_EQ(defaults.process_noise_order, 1);
	try
	{
		loadSlam(ekfSimIniWith("jacobians = first_estimate", "jacobians = fej"));
		FAIL() << "no error for jacobians = fej";
	}
	catch (const mrolr::util::ConfigError& e)
	{
		EXPECT_NE(std::string(e.what()).find("jacobians"), std::string::npos) << e.what();
		EXPECT_NE(std::string(e.what()).find("fej"), std::string::npos) << e.what();
	}
	EXPECT_THROW(loadSlam(ekfSimIniWith("process_noise_order = 2", "process_noise_order = 3")),
	             mrolr::util::ConfigError);
}
