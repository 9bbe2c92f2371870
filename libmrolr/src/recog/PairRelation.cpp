#include <mrolr/recog/PairRelation.h>

#include <algorithm>
#include <cmath>

namespace mrolr::recog
{
namespace
{
double angleBetween(const Eigen::Vector3d& a, const Eigen::Vector3d& b)
{
	return std::acos(std::clamp(a.dot(b), -1.0, 1.0));
}

/** Paper section 3: d, h, q1, q2 and the endpoint intervals of two non-parallel lines. */
void lineLineSkew(const Feature& a, const Feature& b, PairRelation& r)
{
	const Eigen::Vector3d w0 = a.m - b.m;
	const double c = a.u.dot(b.u), d1 = a.u.dot(w0), e = b.u.dot(w0);
	const double denom = 1 - c * c;
	r.q1 = (c * e - d1) / denom;
	r.q2 = (e - c * d1) / denom;
	const Eigen::Vector3d d = a.u.cross(b.u).normalized();
	r.h = (b.m - a.m).dot(d);
	r.lo1 = -0.5 * a.len_mm - r.q1;
	r.hi1 = 0.5 * a.len_mm - r.q1;
	r.lo2 = -0.5 * b.len_mm - r.q2;
	r.hi2 = 0.5 * b.len_mm - r.q2;
}

/** Near-parallel lines: the perpendicular distance of b's midpoint from line a. */
void lineLineParallel(const Feature& a, const Feature& b, PairRelation& r)
{
	const Eigen::Vector3d w = b.m - a.m;
	r.q1 = w.dot(a.u);
	r.h = (w - r.q1 * a.u).norm();
}

/** Line l and conic c: foot of the perpendicular from the centre onto the line. */
void lineConic(const Feature& l, const Feature& c, PairRelation& r)
{
	const double f = (c.m - l.m).dot(l.u);
	const Eigen::Vector3d foot = l.m + f * l.u;
	r.h = (c.m - foot).norm();
	r.lo1 = -0.5 * l.len_mm - f;
	r.hi1 = 0.5 * l.len_mm - f;
	r.ax1 = (foot - c.m).dot(c.u);
}

void conicConic(const Feature& a, const Feature& b, PairRelation& r)
{
	const Eigen::Vector3d w = b.m - a.m;
	r.h = w.norm();
	r.ax1 = w.dot(a.u);
	r.ax2 = -w.dot(b.u);
}

/** The distances and intervals of the relation (everything but the angle). */
void relateGeometry(const Feature& a, const Feature& b, bool parallel, PairRelation& r)
{
	r.parallel = parallel;
	if (a.isLine() && b.isLine())
		parallel ? lineLineParallel(a, b, r) : lineLineSkew(a, b, r);
	else if (a.isLine())
		lineConic(a, b, r);
	else if (b.isLine())
		lineConic(b, a, r);
	else
		conicConic(a, b, r);
}

bool within(double scene, double model, double tol)
{
	return std::abs(scene - model) <= tol;
}

/** A scene segment [lo, hi] must lie inside the model's [lo, hi] widened by tol. */
bool inside(double slo, double shi, double mlo, double mhi, double tol)
{
	return slo >= mlo - tol && shi <= mhi + tol;
}

bool consistentLineLine(const PairRelation& m, const PairRelation& s, const Tolerance& t)
{
	if (m.parallel) return within(s.h, m.h, 2 * t.beta_mm + std::abs(m.q1) * t.tan_theta);
	if (!within(s.h, m.h, skewHTolerance_mm(m, t))) return false;
	const SkewIntervalTolerances tol = skewIntervalTolerances(m, t);
	return inside(s.lo1, s.hi1, m.lo1, m.hi1, tol.first_mm) &&
	       inside(s.lo2, s.hi2, m.lo2, m.hi2, tol.second_mm);
}

bool consistentLineConic(const PairRelation& m, const PairRelation& s, const Tolerance& t)
{
	const double tol = 2 * t.beta_mm + (m.h + std::abs(m.ax1)) * t.tan_theta;
	return within(s.h, m.h, tol) && within(s.ax1, m.ax1, tol) &&
	       inside(s.lo1, s.hi1, m.lo1, m.hi1, tol);
}

bool consistentConicConic(const PairRelation& m, const PairRelation& s, const Tolerance& t)
{
	const double b2 = 2 * t.beta_mm, tol = b2 + m.h * t.tan_theta;
	return within(s.h, m.h, b2) && within(s.ax1, m.ax1, tol) && within(s.ax2, m.ax2, tol);
}

}  // namespace

CosineRange cosineRange(const PairRelation& m, const Tolerance& t)
{
	const double two = 2 * t.theta_rad;
	CosineRange r;
	if (m.alpha - two > 0) r.hi = m.cos_alpha * t.cos_2theta + m.sin_alpha * t.sin_2theta;
	if (m.alpha + two < M_PI) r.lo = m.cos_alpha * t.cos_2theta - m.sin_alpha * t.sin_2theta;
	return r;
}

PairRelation relate(const Feature& a, const Feature& b, bool parallel)
{
	PairRelation r;
	r.alpha = angleBetween(a.u, b.u);
	r.cos_alpha = std::cos(r.alpha);
	r.sin_alpha = std::sin(r.alpha);
	relateGeometry(a, b, parallel, r);
	return r;
}

PairRelation relateModel(const Feature& a, const Feature& b)
{
	const double alpha = angleBetween(a.u, b.u);
	const bool parallel =
	    a.isLine() && b.isLine() && (alpha < kParallelAngle || alpha > M_PI - kParallelAngle);
	return relate(a, b, parallel);
}

namespace
{
/** consistentLineLine for two skew lines, computing the scene pair's h first and the rest only
 * when h agrees (the same values as relateGeometry: most pairs fail on h). */
bool consistentSkew(const PairRelation& m, const Feature& sa, const Feature& sb, const Tolerance& t)
{
	PairRelation s;
	s.h = (sb.m - sa.m).dot(sa.u.cross(sb.u).normalized());
	if (!within(s.h, m.h, skewHTolerance_mm(m, t))) return false;
	lineLineSkew(sa, sb, s);
	return consistentLineLine(m, s, t);
}
}  // namespace

// flatten: every helper above inlined into it (clique matching asks it millions of times a
// search; the calls cost as much as the arithmetic). GCC's attribute; elsewhere none.
#if defined(__GNUC__) && !defined(__clang__)
#define MROLR_FLATTEN __attribute__((flatten))
#else
#define MROLR_FLATTEN
#endif
MROLR_FLATTEN bool consistent(const PairRelation& m, const Feature& ma, const Feature& mb,
                              const Feature& sa, const Feature& sb, const Tolerance& tol)
{
	return consistent(m, cosineRange(m, tol), ma, mb, sa, sb, tol);
}

MROLR_FLATTEN bool consistent(const PairRelation& m, const CosineRange& angle, const Feature& ma,
                              const Feature& mb, const Feature& sa, const Feature& sb,
                              const Tolerance& tol)
{
	if (sa.kind != ma.kind || sb.kind != mb.kind) return false;
	if (!angle.contains(sa.u.dot(sb.u))) return false;
	if (ma.isLine() && mb.isLine() && !m.parallel) return consistentSkew(m, sa, sb, tol);
	PairRelation s;  // the angle was checked above: no trigonometry in the matcher's inner loop
	relateGeometry(sa, sb, m.parallel, s);
	if (ma.isLine() && mb.isLine()) return consistentLineLine(m, s, tol);
	if (ma.isLine() || mb.isLine()) return consistentLineConic(m, s, tol);
	return consistentConicConic(m, s, tol);
}

}  // namespace mrolr::recog
