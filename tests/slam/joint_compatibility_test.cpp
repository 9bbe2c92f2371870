// Joint compatibility of one step's matches (Neira & Tardós 2001): a wrong match that passes its
// own gate, because the vehicle's heading is uncertain, is refused when the other matches pin
// the heading down; right matches are accepted together.
#include "slam_test_util.h"

#include <mrolr/slam/Chi2.h>
#include <mrolr/slam/HeadMeasurement.h>
#include <mrolr/slam/JointCompatibility.h>

#include <gtest/gtest.h>

#include <random>

using namespace mrolr;

namespace
{
/** A vehicle at the origin whose heading is uncertain (σ 0.1 rad), three features known exactly
 * ahead-left, ahead and ahead-right. */
struct Scene
{
	base::LabmateModel model;
	slam::ActiveSlamFilter filter{slamtest::defaultOptions(), model};
	std::vector<Eigen::Vector3d> features{{1.5, 1.2, 4}, {0, 1.5, 5}, {-1.5, 0.8, 4.5}};
	Scene()
	{
		filter.reset({0, 0, 0});
		for (size_t i = 0; i < features.size(); ++i)
			filter.addKnownFeature("F" + std::to_string(i), features[i]);
		Eigen::MatrixXd P = filter.covariance();
		P(2, 2) = 0.01;
		filter.setState(filter.stateVector(), P);
	}
	/** The measurement of feature @p i the true vehicle @p xv gives. */
	Eigen::Vector3d h(size_t i, const Eigen::Vector3d& xv)
	{
		return slam::predictMeasurement(xv, features[i], filter.options().head.constants);
	}
};
}  // namespace

TEST(JointCompatibility, RightMatchesAreAcceptedTogether)
{
	Scene s;
	const Eigen::Vector3d truth(0, 0, 0.05);  // the heading is off by half a sigma
	std::vector<slam::Observation> obs;
	for (size_t i = 0; i < 3; ++i) obs.push_back({i, s.h(i, truth)});
	const auto jc = slam::jointlyCompatible(s.filter, obs, 0.99);
	EXPECT_EQ(jc.accepted, (std::vector<size_t>{0, 1, 2}));
	EXPECT_LT(jc.joint_nis, 1e-3 + slam::chi2Quantile(0.99, 9));
}

TEST(JointCompatibility, APlantedWrongMatchThatPassesItsOwnGateIsRefused)
{
	Scene s;
	const Eigen::Vector3d truth(0, 0, 0);
	std::vector<slam::Observation> obs;
	for (size_t i = 0; i < 3; ++i) obs.push_back({i, s.h(i, truth)});
	obs[1].h[0] += 0.12;  // a match on a rival patch 0.12 rad to the left of feature 1
	// Alone it is plausible: the heading may well be 0.12 rad off (1.2 sigma).
	const Eigen::Vector3d nu = obs[1].h - s.filter.predictedMeasurement(1);
	const double own_nis = nu.dot(s.filter.innovationCovariance(1).ldlt().solve(nu));
	ASSERT_LT(own_nis, slam::chi2Quantile(0.99, 3)) << "the planted match must pass its own gate";
	// With the two right matches, which say the heading is where predicted, it cannot be.
	const auto jc = slam::jointlyCompatible(s.filter, obs, 0.99);
	EXPECT_EQ(jc.accepted, (std::vector<size_t>{0, 2}));
}

TEST(JointCompatibility, TheLargestCompatibleSetWinsWhateverTheOrder)
{
	Scene s;
	const Eigen::Vector3d truth(0, 0, -0.03);
	std::mt19937 rng(7);
	std::normal_distribution<double> n(0, 1e-3);
	for (int trial = 0; trial < 20; ++trial)
	{
		std::vector<slam::Observation> obs;
		for (size_t i = 0; i < 3; ++i)
			obs.push_back({i, s.h(i, truth) + Eigen::Vector3d(n(rng), n(rng), n(rng))});
		const size_t wrong = static_cast<size_t>(trial % 3);
		obs[wrong].h[0] -= 0.15;
		std::shuffle(obs.begin(), obs.end(), rng);
		const auto jc = slam::jointlyCompatible(s.filter, obs, 0.99);
		ASSERT_EQ(jc.accepted.size(), 2u) << trial;
		for (size_t a : jc.accepted) EXPECT_NE(obs[a].feature, wrong) << trial;
	}
}
