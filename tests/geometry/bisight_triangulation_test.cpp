// Stereo triangulation with the head (thesis 4.2.5) and its covariance.
#include <mrolr/geometry/BiSightHead.h>

#include "geometry_test_util.h"

#include <gtest/gtest.h>

using namespace mrolr::geometry;
using mrolr::geometry::test_util::numericJacobian;

namespace
{
BiSightHead testHead()
{
	return BiSightHead(test_util::offsetTestOptions());
}
}  // namespace

TEST(BiSightTriangulation, InvertsProjectionAtAnyAngles)
{
	const BiSightHead head = testHead();
	std::mt19937 rng(6);
	for (int k = 0; k < 500; ++k)
	{
		const Eigen::Vector3d m = test_util::randomPointAhead(rng);
		const HeadAngles a = test_util::randomAnglesLookingNear(head, m, rng);
		const Triangulation t = head.triangulate(head.project(m, a), a);
		EXPECT_LT((t.p_GinC0 - m).norm(), 1e-9 * m.norm()) << m.transpose();
		EXPECT_LT(t.gap_m, 1e-9);
		EXPECT_TRUE(head.triangulatePoint(head.project(m, a), a).isApprox(t.p_GinC0, 1e-15));
	}
}

TEST(BiSightTriangulation, PixelJacobianMatchesCentralDifferences)
{
	const BiSightHead head = testHead();
	std::mt19937 rng(7);
	for (int k = 0; k < 100; ++k)
	{
		const Eigen::Vector3d m = test_util::randomPointAhead(rng);
		const HeadAngles a = test_util::randomAnglesLookingNear(head, m, rng);
		// Noisy pixels, so the rays are skew and the midpoint is not an exact intersection.
		std::normal_distribution<double> noise(0, 2);
		Eigen::Vector4d px = head.project(m, a).asVector();
		for (int i = 0; i < 4; ++i) px[i] += noise(rng);
		const auto f = [&](const Eigen::Vector4d& x)
		{ return head.triangulatePoint(StereoPixels::fromVector(x), a); };
		const auto num = numericJacobian<3, 4>(f, px, 1e-4);
		const Eigen::Matrix<double, 3, 4> J =
		    head.triangulate(StereoPixels::fromVector(px), a).J_wrt_pixels;
		EXPECT_LT((J - num).cwiseAbs().maxCoeff(), 1e-6 * (1 + num.cwiseAbs().maxCoeff()))
		    << "analytic\n"
		    << J << "\nnumeric\n"
		    << num;
	}
}

TEST(BiSightTriangulation, CovarianceMatchesMonteCarloOfPixelNoise)
{
	const BiSightHead head = testHead();
	const Eigen::Vector3d m(0.3, 0.2, 2.5);
	HeadAngles a = head.fixate(m);
	a.pan += 0.03;  // not fixating
	const StereoPixels px = head.project(m, a);
	const double sigma = 0.5;
	const Eigen::Matrix3d cov = head.triangulate(px, a, sigma).cov;
	std::mt19937 rng(8);
	std::normal_distribution<double> noise(0, sigma);
	const int N = 4000;
	Eigen::Matrix3d sample = Eigen::Matrix3d::Zero();
	double nees = 0;
	for (int k = 0; k < N; ++k)
	{
		Eigen::Vector4d x = px.asVector();
		for (int i = 0; i < 4; ++i) x[i] += noise(rng);
		const Eigen::Vector3d e = head.triangulatePoint(StereoPixels::fromVector(x), a) - m;
		sample += e * e.transpose() / N;
		nees += e.dot(cov.ldlt().solve(e)) / N;
	}
	for (int i = 0; i < 3; ++i)
		EXPECT_NEAR(std::sqrt(sample(i, i)), std::sqrt(cov(i, i)), 0.05 * std::sqrt(cov(i, i)));
	// Mean NEES of a consistent 3-D estimate is 3; with N = 4000 its 99.9% band is about ±0.2.
	EXPECT_NEAR(nees, 3.0, 0.25);
	// Depth dominates: the thesis's Fig 5.3.1.3 ellipse, ΔZ ≫ ΔX.
	EXPECT_GT(cov(2, 2), 10 * cov(0, 0));
}

TEST(BiSightTriangulation, RejectsParallelAndDivergingRays)
{
	const BiSightHead head = testHead();
	// Vergence zero and both pixels on the principal point: parallel optic axes.
	EXPECT_THROW(head.triangulate({318.5, 244.25, 318.5, 244.25}, {}), TriangulationError);
	// A point 20 km away projected with converging cameras: near-parallel.
	const Eigen::Vector3d far(0, 0, 2e4);
	const HeadAngles a{0, 0, -0.01, 0.01};
	EXPECT_THROW(head.triangulate(head.project(far, a), a), TriangulationError);
	// The left ray turned left and the right ray turned right meet behind the cameras.
	try
	{
		head.triangulate({218.5, 244.25, 418.5, 244.25}, {});
		FAIL() << "expected TriangulationError";
	}
	catch (const TriangulationError& e)
	{
		EXPECT_NE(std::string(e.what()).find("behind"), std::string::npos) << e.what();
	}
	EXPECT_THROW(head.triangulate({318.5, 244.25, 300, 244.25}, {}, -1), GeometryError);
}
