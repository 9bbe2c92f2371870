#pragma once
/** The arc a circle's covered angle bins span (turntable model building: a rim kept where the
 * views show it). */

#include <array>
#include <cmath>
#include <cstddef>
#include <utility>

namespace mrolr::model
{
/** The circle minus its longest run of uncovered bins, as (t1, t2) in rad with t1 <= t2, for a
 * circle's angle cut into N equal bins, bin 0 starting at @p start_rad; (0, 2π) when every bin is
 * covered, an empty arc when none is. */
template <std::size_t N>
std::pair<double, double> arcOfBins(const std::array<bool, N>& bins, double start_rad)
{
	const int n = static_cast<int>(N);
	int gap_start = 0, gap_len = 0;
	for (int s = 0; s < n; ++s)
	{
		int len = 0;
		while (len < n && !bins[static_cast<std::size_t>((s + len) % n)]) ++len;
		if (len > gap_len) gap_len = len, gap_start = s;
	}
	if (gap_len == 0) return {0.0, 2 * M_PI};
	const double bin = 2 * M_PI / n;
	const double t1 = start_rad + (gap_start + gap_len) * bin;
	return {t1, t1 + (n - gap_len) * bin};
}

}  // namespace mrolr::model
