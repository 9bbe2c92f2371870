#include "recog_test_util.h"

#include <mrolr/recog/PoseEstimation.h>
#include <mrolr/recog/TransformCluster.h>
#include <mrolr/sim/SyntheticObjects.h>
#include <mrolr/sim/SyntheticScene.h>

#include <gtest/gtest.h>
#include <Eigen/Geometry>

#include <algorithm>
#include <random>

using namespace mrolr::recog;
using namespace mrolr::sim;

namespace
{
std::vector<Correspondence> exactCorrespondences(const mrolr::model::WireFrame& wf,
                                                 const Eigen::Isometry3d& T)
{
	std::vector<Correspondence> cs;
	for (const auto& f : featuresOf(wf)) cs.push_back({f, f.transformed(T)});
	return cs;
}

Eigen::Isometry3d poseFor(int k)
{
	return tablePose(40.0 * k + 5, 10.0 * k - 30, Eigen::Vector3d(20 * k, -100, 800));
}
}  // namespace

// Faugeras–Hebert recovers an exact pose from every lab object's features.
TEST(pose, FaugerasHebertExact)
{
	int k = 0;
	for (const auto& wf : makeLabObjects())
	{
		const auto T = poseFor(k++);
		const auto est = faugerasHebertPose(exactCorrespondences(wf, T));
		ASSERT_TRUE(est) << wf.name;
		EXPECT_LT((est->matrix() - T.matrix()).cwiseAbs().maxCoeff(), 1e-9) << wf.name;
	}
}

// The quaternion rotation agrees with Eigen's SVD-based Umeyama on noisy directions (both
// minimise the same sum of squares), fed as ± pairs so the centroid is zero.
TEST(pose, QuaternionRotationAgreesWithEigenUmeyama)
{
	std::mt19937 rng(3);
	std::normal_distribution<> n(0, 0.05);
	const Eigen::Matrix3d R = poseFor(3).linear();
	std::vector<Eigen::Vector3d> a, b;
	Eigen::Matrix<double, 3, Eigen::Dynamic> A(3, 20), B(3, 20);
	for (int i = 0; i < 10; ++i)
	{
		a.push_back(Eigen::Vector3d::Random().normalized());
		b.push_back((R * a.back() + Eigen::Vector3d(n(rng), n(rng), n(rng))).normalized());
		A.col(2 * i) = a.back(), A.col(2 * i + 1) = -a.back();
		B.col(2 * i) = b.back(), B.col(2 * i + 1) = -b.back();
	}
	const auto q = rotationFromDirections(a, b, std::vector<double>(10, 1.0));
	ASSERT_TRUE(q);
	const Eigen::Matrix3d U = Eigen::umeyama(A, B, false).block<3, 3>(0, 0);
	EXPECT_LT(rotationDistanceDeg(*q, U), 1e-6);
	EXPECT_GT(rotationDistanceDeg(*q, R),
	          0.1);  // the noise moved it: the comparison is not trivial
}

// Parallel directions alone do not fix a rotation; that is reported, not guessed.
TEST(pose, DegenerateRotationReported)
{
	const std::vector<Eigen::Vector3d> a = {Eigen::Vector3d::UnitZ(), -Eigen::Vector3d::UnitZ()};
	const std::vector<Eigen::Vector3d> b = {Eigen::Vector3d::UnitX(), -Eigen::Vector3d::UnitX()};
	EXPECT_FALSE(rotationFromDirections(a, b, {1, 1}));
}

// Fragments do not bias the translation: lines are constrained only perpendicular to themselves.
TEST(pose, FragmentsKeepThePoseExact)
{
	const auto wf = makeStaplerBox();
	const auto T = poseFor(2);
	auto cs = exactCorrespondences(wf, T);
	for (auto& c : cs)
		if (c.scene.isLine())
		{
			c.scene.p2 = c.scene.p1 + 0.4 * (c.scene.p2 - c.scene.p1);
			c.scene.m = 0.5 * (c.scene.p1 + c.scene.p2);
			c.scene.len_mm *= 0.4;
		}
	const auto est = faugerasHebertPose(cs);
	ASSERT_TRUE(est);
	EXPECT_LT((est->matrix() - T.matrix()).cwiseAbs().maxCoeff(), 1e-9);
}

// OpenGV's Arun on the derived points (conic centres, common-perpendicular midpoints) gives the
// same pose as Faugeras–Hebert on exact data, and stays close on noisy data.
TEST(pose, OpengvArunAgreesWithFaugerasHebert)
{
	std::mt19937 rng(11);
	std::normal_distribution<> n(0, 0.3);
	int k = 0;
	for (const auto& wf : makeLabObjects())
	{
		const auto T = poseFor(k++);
		auto cs = exactCorrespondences(wf, T);
		const auto exact = arunPose(cs, 2.0);
		ASSERT_TRUE(exact) << wf.name;
		EXPECT_LT((exact->matrix() - T.matrix()).cwiseAbs().maxCoeff(), 1e-6) << wf.name;
		for (auto& c : cs)
		{
			const Eigen::Vector3d d1(n(rng), n(rng), n(rng)), d2(n(rng), n(rng), n(rng));
			c.scene.p1 += d1, c.scene.p2 += d2, c.scene.m += 0.5 * (d1 + d2);
			if (c.scene.isLine()) c.scene.u = (c.scene.p2 - c.scene.p1).normalized();
		}
		const auto fh = faugerasHebertPose(cs);
		const auto arun = arunPose(cs, 2.0);
		ASSERT_TRUE(fh && arun) << wf.name;
		EXPECT_LT(rotationDistanceDeg(fh->linear(), T.linear()), 1.5) << wf.name;
		EXPECT_LT(rotationDistanceDeg(arun->linear(), T.linear()), 3.0) << wf.name;
		EXPECT_LT((arun->translation() - fh->translation()).norm(), 10.0) << wf.name;
	}
}

// Too few derived points: no Arun estimate.
TEST(pose, ArunNeedsThreePoints)
{
	const auto wf = makeStaplerBox();
	auto cs = exactCorrespondences(wf, poseFor(1));
	cs.resize(2);  // two parallel edges: no common perpendicular, no conic
	EXPECT_FALSE(arunPose(cs, 2.0));
	auto can = exactCorrespondences(makeCan(), poseFor(1));
	can.erase(
	    std::remove_if(can.begin(), can.end(), [](const auto& c) { return c.model.isLine(); }),
	    can.end());
	ASSERT_EQ(can.size(), 5u);  // four coaxial circles and the ring-pull arc: nearly collinear
	EXPECT_TRUE(arunPose(can, 2.0));  // the ring-pull centre is 18 mm off the axis
	can.pop_back();
	EXPECT_FALSE(arunPose(can, 2.0));  // only the coaxial circles: collinear centres
	EXPECT_FALSE(arunPose(can, 2.0));
}

// Clustering: two groups of transforms are separated, each mean is inside its group, and the
// spread is the RMS of the perturbations.
TEST(cluster, SeparatesGroupsAndReportsSpread)
{
	const Eigen::Vector3d c(0, 0, 50);
	std::vector<PoseHypothesis> hyps;
	const auto A = poseFor(1), B = poseFor(4);
	for (int i = -1; i <= 1; i += 2)
	{
		Eigen::Isometry3d Ta = A;
		Ta.rotate(Eigen::AngleAxisd(i * 1.0 * M_PI / 180, Eigen::Vector3d::UnitZ()));
		hyps.push_back({Ta, 3});
		Eigen::Isometry3d Tb = B;
		Tb.pretranslate(Eigen::Vector3d(i * 2.0, 0, 0));
		hyps.push_back({Tb, 1});
	}
	const auto cl = clusterTransforms(hyps, c, 3, 6);
	ASSERT_EQ(cl.size(), 2u);
	EXPECT_EQ(cl[0].members.size(), 2u);
	EXPECT_LT(rotationDistanceDeg(cl[0].mean.linear(), A.linear()), 1e-9);
	EXPECT_NEAR(cl[0].spread_rot_deg, 1.0, 1e-9);
	EXPECT_LT((cl[1].mean.translation() - B.translation()).norm(), 1e-9);
	EXPECT_NEAR(cl[1].spread_trans_mm, 2.0, 1e-9);
	EXPECT_EQ(clusterTransforms(hyps, c, 0.5, 6).size(), 3u);  // tighter: A's pair splits
}

// Only the heaviest clusters wanted: they are the full clustering's first ones, the same members,
// weights, means and spreads, to the bit. Light hypotheses come first in the input and the
// heaviest cluster is made of many light ones, so clusters cut before their order is known fail.
TEST(cluster, TheHeaviestClustersAloneAreTheFullClusteringsFirst)
{
	std::mt19937 rng(5);
	std::uniform_real_distribution<double> jitter(-0.5, 0.5);
	const Eigen::Vector3d c(0, 0, 50);
	std::vector<PoseHypothesis> hyps;
	for (int g = 0; g < 12; ++g)  // group g: g + 1 hypotheses of weight 12 - g, about pose g
		for (int i = 0; i <= g; ++i)
		{
			Eigen::Isometry3d T = poseFor(g);
			T.pretranslate(Eigen::Vector3d(100.0 * g + jitter(rng), jitter(rng), jitter(rng)));
			T.rotate(Eigen::AngleAxisd(jitter(rng) * M_PI / 180, Eigen::Vector3d::UnitX()));
			hyps.push_back({T, 12.0 - g});
		}
	const auto all = clusterTransforms(hyps, c, 3, 6);
	ASSERT_EQ(all.size(), 12u);
	EXPECT_GE(all.front().members.size(), 6u);  // the heaviest: many light hypotheses
	for (const size_t n : {size_t{0}, size_t{1}, size_t{5}, size_t{12}, size_t{20}})
	{
		const auto first = clusterTransforms(hyps, c, 3, 6, n);
		ASSERT_EQ(first.size(), std::min(n, all.size()));
		for (size_t k = 0; k < first.size(); ++k)
		{
			EXPECT_EQ(first[k].members, all[k].members) << n << " " << k;
			EXPECT_EQ(first[k].weight, all[k].weight);
			EXPECT_TRUE(first[k].mean.matrix() == all[k].mean.matrix());
			EXPECT_EQ(first[k].spread_rot_deg, all[k].spread_rot_deg);
			EXPECT_EQ(first[k].spread_trans_mm, all[k].spread_trans_mm);
		}
	}
}
