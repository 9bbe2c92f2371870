#include "BenchProblem.h"

#include <cmath>

namespace mrolr::bench
{
BenchProblem::BenchProblem(int features, unsigned seed) : N(features), rng(seed)
{
	R = Eigen::Vector3d(4e-6, 1e-4, 4e-6).asDiagonal();
	const int n = 3 + 3 * N, k = 20;
	std::uniform_real_distribution<double> bearing(-M_PI, M_PI), range(4.0, 8.0), height(2.0, 3.0);
	x0 = Eigen::VectorXd::Zero(n);
	for (int i = 0; i < N; ++i)
	{
		const double b = bearing(rng), r = range(rng);
		x0.segment<3>(3 + 3 * i) << r * std::sin(b), height(rng), r * std::cos(b);
	}
	// Low-rank correlations keep the set-up O(n²) even for N = 1000.
	Eigen::MatrixXd L(n, k);
	for (Eigen::Index j = 0; j < L.size(); ++j) L.data()[j] = normal(rng);
	P0 = 1e-2 * L * L.transpose() / k;
	P0.diagonal().array() += 1e-4;
}

Eigen::Vector3d BenchProblem::measure(const Eigen::Vector3d& x_v, const Eigen::Vector3d& y_i)
{
	Eigen::Vector3d z = slam::predictMeasurement(x_v, y_i, head);
	for (int c = 0; c < 3; ++c) z[c] += std::sqrt(R(c, c)) * normal(rng);
	return z;
}

}  // namespace mrolr::bench
