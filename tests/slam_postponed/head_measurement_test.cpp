// The test measurement model's analytic Jacobian against central differences at random states.

#include "HeadMeasurement.h"

#include <gtest/gtest.h>

#include <random>

using mrolr::slam::test::headJacobian;
using mrolr::slam::test::headMeasure;

TEST(PostponedTestModel, HeadJacobianMatchesCentralDifferences)
{
	std::mt19937 rng(5);
	std::uniform_real_distribution<double> u(-3, 3);
	const double I = 0.25, h = 1e-6;
	for (int trial = 0; trial < 50; ++trial)
	{
		Eigen::Matrix<double, 6, 1> s;
		s << u(rng), u(rng), u(rng), u(rng) + 7, u(rng) * 0.3 + 1, u(rng) + 7;
		const auto f = [&](const Eigen::Matrix<double, 6, 1>& v)
		{ return headMeasure(v.head<3>(), v.tail<3>(), I); };
		Eigen::Matrix<double, 3, 6> num;
		for (int k = 0; k < 6; ++k)
		{
			Eigen::Matrix<double, 6, 1> a = s, b = s;
			a[k] += h;
			b[k] -= h;
			num.col(k) = (f(a) - f(b)) / (2 * h);
		}
		EXPECT_LT((headJacobian(s.head<3>(), s.tail<3>(), I) - num).cwiseAbs().maxCoeff(), 1e-7)
		    << "trial " << trial;
	}
}
