#include <mrolr/recog/PairPrefilter.h>
#include <mrolr/util/SimdClones.h>

#include <algorithm>
#include <cmath>

namespace mrolr::recog
{
namespace
{
// consistent() compares with margins of 1e-12 (angle) and exact bounds (h); these widen them by
// far more than the few ulps by which the two computations can differ
constexpr double kCosSlack = 1e-9, kHSlack_mm = 1e-6;

/** The terms of the quick test, by value so that the stores to keep cannot alias them. */
struct Quick
{
	double ax, ay, az, amx, amy, amz;  ///< the matched scene feature a
	double cos_lo, cos_hi;             ///< the angle test's range, widened
	bool skew;                         ///< test h and the intervals too
	double h, h_tol;                   ///< the model's h and its tolerance, widened
	/// consistentLineLine's bounds on the scene pair's intervals (lineLineSkew), widened, as
	/// bounds on q1 and, less half the scene segment's length, on q2
	double q1_min, q1_max, q2_min, q2_max;
};

MROLR_SIMD_CLONES void quickTest(const Quick q, const PackedFeatures::Arrays p, size_t n,
                                 std::int64_t* keep)
{
	for (size_t k = 0; k < n; ++k)
	{
		const double c = q.ax * p.ux[k] + q.ay * p.uy[k] + q.az * p.uz[k];
		const bool angle = (c >= q.cos_lo) & (c <= q.cos_hi);
		// h = (m_b − m_a) · (u_a × u_b) / |u_a × u_b|, compared without the division
		const double cx = q.ay * p.uz[k] - q.az * p.uy[k], cy = q.az * p.ux[k] - q.ax * p.uz[k],
		             cz = q.ax * p.uy[k] - q.ay * p.ux[k];
		const double r = std::sqrt(cx * cx + cy * cy + cz * cz);
		const double h_r = (p.mx[k] - q.amx) * cx + (p.my[k] - q.amy) * cy + (p.mz[k] - q.amz) * cz;
		const bool near = std::abs(h_r - q.h * r) <= q.h_tol * r;
		// the common perpendicular's feet q1 = x1 / den, q2 = x2 / den (lineLineSkew) within
		// their bounds, compared without the division (den > 0; at 0 the pair is kept)
		const double wx = q.amx - p.mx[k], wy = q.amy - p.my[k], wz = q.amz - p.mz[k];
		const double d1 = q.ax * wx + q.ay * wy + q.az * wz;
		const double e = p.ux[k] * wx + p.uy[k] * wy + p.uz[k] * wz;
		const double den = 1 - c * c, x1 = c * e - d1, x2 = e - c * d1, half = 0.5 * p.len[k];
		const bool inside =
		    (den <= 0) | ((x1 >= q.q1_min * den) & (x1 <= q.q1_max * den) &
		                  (x2 >= (q.q2_min + half) * den) & (x2 <= (q.q2_max - half) * den));
		const bool skew_ok = near & inside;
		keep[k] = static_cast<std::int64_t>(angle & (!q.skew | skew_ok));
	}
}
}  // namespace

void PackedFeatures::push_back(const Feature& f)
{
	ux.push_back(f.u.x()), uy.push_back(f.u.y()), uz.push_back(f.u.z());
	mx.push_back(f.m.x()), my.push_back(f.m.y()), mz.push_back(f.m.z());
	len.push_back(f.len_mm);
}

PackedFeatures::Arrays PackedFeatures::arrays() const
{
	return {ux.data(), uy.data(), uz.data(), mx.data(), my.data(), mz.data(), len.data()};
}

void mayBeConsistent(const PairRelation& m, const Feature& ma, const Feature& mb, const Feature& a,
                     const PackedFeatures& packed, const Tolerance& tol,
                     std::vector<std::int64_t>& keep)
{
	const CosineRange angle = cosineRange(m, tol);
	Quick q{};
	q.ax = a.u.x(), q.ay = a.u.y(), q.az = a.u.z();
	q.amx = a.m.x(), q.amy = a.m.y(), q.amz = a.m.z();
	q.cos_lo = angle.lo - kCosSlack, q.cos_hi = angle.hi + kCosSlack;
	q.skew = ma.isLine() && mb.isLine() && !m.parallel;
	// consistentLineLine's bounds for two skew lines: on h, then on the intervals
	const SkewIntervalTolerances t = skewIntervalTolerances(m, tol);
	q.h = m.h;
	q.h_tol = skewHTolerance_mm(m, tol) + kHSlack_mm;
	// −len/2 − q >= lo − tol and len/2 − q <= hi + tol, for the scene's first and second segment
	q.q1_min = 0.5 * a.len_mm - (m.hi1 + t.first_mm) - kHSlack_mm;
	q.q1_max = -0.5 * a.len_mm - (m.lo1 - t.first_mm) + kHSlack_mm;
	q.q2_min = -(m.hi2 + t.second_mm) - kHSlack_mm;
	q.q2_max = -(m.lo2 - t.second_mm) + kHSlack_mm;
	keep.resize(packed.size());
	quickTest(q, packed.arrays(), packed.size(), keep.data());
}

}  // namespace mrolr::recog
