#include <mrolr/slam/Chi2.h>

#include <unsupported/Eigen/SpecialFunctions>

#include <stdexcept>

namespace mrolr::slam
{
double chi2Quantile(double p, unsigned dof)
{
	if (!(p > 0 && p < 1) || dof < 1)
		throw std::invalid_argument("chi2Quantile: need 0 < p < 1 and dof >= 1");
	// CDF of χ²_k at x is the regularised lower incomplete gamma P(k/2, x/2).
	const auto cdf = [dof](double x) { return Eigen::numext::igamma(0.5 * dof, 0.5 * x); };
	double lo = 0, hi = 2.0 * dof + 10;
	while (cdf(hi) < p) hi *= 2;
	for (int k = 0; k < 200 && hi - lo > 1e-12 * hi; ++k)
	{
		const double mid = 0.5 * (lo + hi);
		(cdf(mid) < p ? lo : hi) = mid;
	}
	return 0.5 * (lo + hi);
}

}  // namespace mrolr::slam
