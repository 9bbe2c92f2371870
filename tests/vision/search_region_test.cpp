// Search ellipses (thesis eqs 5.37-5.39): U = J S J^T agrees with Monte-Carlo projection of the
// innovation, and the ellipse gates the patch search.
#include "TestScene.h"

#include <mrolr/geometry/IdealHead.h>
#include <mrolr/vision/PatchSearch.h>
#include <mrolr/vision/SearchRegion.h>

#include <gtest/gtest.h>

#include <Eigen/Cholesky>
#include <random>

using namespace mrolr;
using namespace mrolr::vision;

TEST(SearchRegion, EllipseCoversTheMonteCarloSpreadOfTheInnovation)
{
	const auto head = test::configuredHead();
	const double I = head.options().interocular_m;
	const Eigen::Vector3d p(0.4, 0.3, 3.0);
	const Eigen::Vector3d h = geometry::idealHeadMeasure(p, I);
	Eigen::Matrix3d S = Eigen::Vector3d(4e-5, 2e-5, 1e-6).asDiagonal();
	S(0, 1) = S(1, 0) = 1e-5;
	const auto angles = head.fixate(p);
	for (auto side : {geometry::Side::Left, geometry::Side::Right})
	{
		const ImageEllipse e = projectInnovation(head, side, angles, h, S, 3.0);
		std::mt19937 rng(3);
		std::normal_distribution<double> n01;
		const Eigen::Matrix3d L = S.llt().matrixL();
		int inside = 0, total = 4000;
		for (int k = 0; k < total; ++k)
		{
			const Eigen::Vector3d hk = h + L * Eigen::Vector3d(n01(rng), n01(rng), n01(rng));
			const auto px = head.project(geometry::idealHeadInverse(hk, I), angles);
			const Eigen::Vector2d uv = side == geometry::Side::Left ? Eigen::Vector2d(px.uL, px.vL)
			                                                        : Eigen::Vector2d(px.uR, px.vR);
			inside += e.contains(uv);
		}
		// P(chi2_2 <= 9) = 0.989 for the 3-sigma ellipse of a Gaussian
		EXPECT_NEAR(double(inside) / total, 0.989, 0.01);
		EXPECT_GT(e.area(), 10.0);
	}
}

TEST(SearchRegion, EllipseGatesTheSearch)
{
	cv::Mat im(200, 300, CV_8UC1, cv::Scalar(90));
	const cv::Mat tex = makeTexture(31, 4);
	tex.copyTo(im(cv::Rect(50 - 15, 100 - 15, 31, 31)));   // inside the ellipse
	tex.copyTo(im(cv::Rect(220 - 15, 100 - 15, 31, 31)));  // identical copy outside it
	const cv::Mat patch = tex(cv::Rect(9, 9, 13, 13)).clone();
	ImageEllipse e;
	e.centre = {215, 98};
	e.cov = Eigen::Vector2d(400, 100).asDiagonal();  // 60 x 30 px half-axes at 3 sigma
	PatchMatch m = searchEllipse(im, patch, e, 0.9);
	ASSERT_TRUE(m.found);
	EXPECT_NEAR(m.uv.x(), 220, 0.5);
	EXPECT_NEAR(m.uv.y(), 100, 0.5);
	// move the ellipse so that only the far copy lies outside: the near one is found
	e.centre = {70, 100};
	e.cov = Eigen::Vector2d(100, 100).asDiagonal();
	m = searchEllipse(im, patch, e, 0.9);
	ASSERT_TRUE(m.found);
	EXPECT_NEAR(m.uv.x(), 50, 0.5);
	// an ellipse that holds neither copy finds nothing
	e.centre = {110, 100};
	e.cov = Eigen::Matrix2d::Identity() * 25;
	m = searchEllipse(im, patch, e, 0.9);
	EXPECT_FALSE(m.found);
	EXPECT_GT(m.candidates, 600);
	EXPECT_LT(m.candidates, 750);  // pi * 15^2 = 707 centres
}
