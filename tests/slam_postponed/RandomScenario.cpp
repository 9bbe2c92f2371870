#include "RandomScenario.h"

#include <cmath>

namespace mrolr::slam::test
{
RandomScenario::RandomScenario(const ScenarioOptions& options)
    : options_(options), rng_(options.seed)
{
	// Thesis sample-run noise, rad² (issue 3, eq 5.41).
	R_ = Eigen::Vector3d(4e-6, 1e-4, 4e-6).asDiagonal();
	const int N = options.features, n = 3 + 3 * N;
	std::uniform_real_distribution<double> bearing(-M_PI, M_PI), range(2.0, 6.0), height(1.5, 3.0);
	x0_ = Eigen::VectorXd::Zero(n);
	for (int i = 0; i < N; ++i)
	{
		const double b = bearing(rng_), r = range(rng_);
		x0_.segment<3>(3 + 3 * i) << r * std::sin(b), height(rng_), r * std::cos(b);
	}
	// Correlated, well-conditioned prior: 1e-2·B Bᵀ/n + 1e-4·I (about 0.1 m of uncertainty).
	Eigen::MatrixXd B(n, n);
	for (Eigen::Index k = 0; k < B.size(); ++k) B.data()[k] = normal(1.0);
	P0_ = 1e-2 * B * B.transpose() / n + 1e-4 * Eigen::MatrixXd::Identity(n, n);
	truth_ = x0_;
	for (Eigen::Index k = 0; k < n; ++k) truth_[k] += normal(0.05);
}

base::WheelControl RandomScenario::nextControl()
{
	std::uniform_real_distribution<double> v(-0.10, 0.15);
	const base::WheelControl u{v(rng_), v(rng_), 1.0};
	const Eigen::Matrix2d U = model_.controlCovariance(u);
	const base::WheelControl noisy{u.v1_mps + normal(std::sqrt(U(0, 0))),
	                               u.v2_mps + normal(std::sqrt(U(1, 1))), u.dt_s};
	truth_.head<3>() = model_.move(truth_.head<3>(), noisy);
	return u;
}

Eigen::Vector3d RandomScenario::measure(int i)
{
	Eigen::Vector3d z =
	    predictMeasurement(truth_.head<3>(), truth_.segment<3>(3 + 3 * i), options_.head);
	for (int k = 0; k < 3; ++k) z[k] += normal(std::sqrt(R_(k, k)));
	return z;
}

int RandomScenario::nextFeature(int current)
{
	const int N = options_.features;
	if (N == 1) return 0;
	std::uniform_int_distribution<int> pick(0, N - 2);
	const int j = pick(rng_);
	return j >= current ? j + 1 : j;
}

int RandomScenario::trackLength()
{
	return std::uniform_int_distribution<int>(1, options_.max_track_steps)(rng_);
}

}  // namespace mrolr::slam::test
