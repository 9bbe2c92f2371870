#include <mrolr/recog/PairPrefilter.h>
#include <mrolr/util/SimdClones.h>

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
	bool skew;                         ///< test h too
	double h, h_tol;                   ///< the model's h and its tolerance, widened
};

MROLR_SIMD_CLONES void quickTest(const Quick q, const double* ux, const double* uy,
                                 const double* uz, const double* mx, const double* my,
                                 const double* mz, size_t n, std::int64_t* keep)
{
	for (size_t k = 0; k < n; ++k)
	{
		const double c = q.ax * ux[k] + q.ay * uy[k] + q.az * uz[k];
		const bool angle = (c >= q.cos_lo) & (c <= q.cos_hi);
		// h = (m_b − m_a) · (u_a × u_b) / |u_a × u_b|, compared without the division
		const double cx = q.ay * uz[k] - q.az * uy[k], cy = q.az * ux[k] - q.ax * uz[k],
		             cz = q.ax * uy[k] - q.ay * ux[k];
		const double r = std::sqrt(cx * cx + cy * cy + cz * cz);
		const double h_r = (mx[k] - q.amx) * cx + (my[k] - q.amy) * cy + (mz[k] - q.amz) * cz;
		const bool near = std::abs(h_r - q.h * r) <= q.h_tol * r;
		keep[k] = static_cast<std::int64_t>(angle & (!q.skew | near));
	}
}
}  // namespace

void PackedFeatures::push_back(const Feature& f)
{
	ux.push_back(f.u.x()), uy.push_back(f.u.y()), uz.push_back(f.u.z());
	mx.push_back(f.m.x()), my.push_back(f.m.y()), mz.push_back(f.m.z());
}

void mayBeConsistent(const PairRelation& m, const Feature& ma, const Feature& mb, const Feature& a,
                     const PackedFeatures& packed, const Tolerance& tol,
                     std::vector<std::int64_t>& keep)
{
	const CosineRange angle = cosineRange(m, tol);
	Quick q{a.u.x(),
	        a.u.y(),
	        a.u.z(),
	        a.m.x(),
	        a.m.y(),
	        a.m.z(),
	        angle.lo - kCosSlack,
	        angle.hi + kCosSlack,
	        ma.isLine() && mb.isLine() && !m.parallel,
	        m.h,
	        0};
	// consistentLineLine's bound on h for two skew lines
	q.h_tol = 2 * tol.beta_mm + (std::abs(m.q1) + std::abs(m.q2)) * tol.tan_theta + kHSlack_mm;
	keep.resize(packed.size());
	quickTest(q, packed.ux.data(), packed.uy.data(), packed.uz.data(), packed.mx.data(),
	          packed.my.data(), packed.mz.data(), packed.size(), keep.data());
}

}  // namespace mrolr::recog
