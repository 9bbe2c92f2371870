#include "ArcFunctions.h"

#include <cmath>

namespace mrolr::base::detail
{
namespace
{
// Below this |θ| the closed forms lose digits to cancellation; the series (truncated after the
// θ⁶ terms) is exact to double precision there.
constexpr double kSeriesBelow = 1e-2;

ArcTerms seriesTerms(double t)
{
	const double t2 = t * t;
	ArcTerms r{};
	r.a = 1 - t2 / 6 * (1 - t2 / 20 * (1 - t2 / 42));
	r.b = t / 2 * (1 - t2 / 12 * (1 - t2 / 30 * (1 - t2 / 56)));
	r.da = -t / 3 * (1 - t2 / 10 * (1 - t2 / 28));
	r.db = 0.5 - t2 / 8 + t2 * t2 / 144 - t2 * t2 * t2 / 5760;
	return r;
}
}  // namespace

ArcTerms arcTerms(double t)
{
	if (std::abs(t) < kSeriesBelow) return seriesTerms(t);
	const double s = std::sin(t), c = std::cos(t);
	ArcTerms r{};
	r.a = s / t;
	r.b = (1 - c) / t;
	r.da = (t * c - s) / (t * t);
	r.db = (t * s - (1 - c)) / (t * t);
	return r;
}

}  // namespace mrolr::base::detail
