#pragma once
/** χ² quantiles for gating (NIS) and consistency bounds (NEES). MRPT 2.5's chi2inv() and chi2CDF()
 * are approximations (chi2inv(0.99, 3) = 11.369 instead of 11.345, chi2inv(0.95, 1) = 3.747 instead
 * of 3.841); this inverts the exact CDF, Eigen's regularised incomplete gamma, by bisection. */

namespace mrolr::slam
{
/** x such that P(χ²_dof ≤ x) = p, to 1e-10 relative; throws std::invalid_argument unless
 * 0 < p < 1 and dof ≥ 1. */
double chi2Quantile(double p, unsigned dof);

}  // namespace mrolr::slam
