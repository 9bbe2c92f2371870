#pragma once
/** Pairwise geometric relations between two features and their error intervals (thesis 6.3 and
 * 6.3.1; paper section 3.1). For a line pair: orientation difference alpha = acos(e1·e2), the
 * minimum distance h between the extended lines (signed along d = e1×e2/|e1×e2|, or the
 * perpendicular distance when near-parallel), and each segment's endpoints measured along its line
 * from the point of closest approach (the paper's s, t). Line–conic and conic–conic pairs use the
 * analogous quantities: the angle between direction and normal, the centre-to-line distance, the
 * axial offsets along the normals and the centre-to-centre distance. All lengths mm, angles rad. */

#include <mrolr/recog/Feature.h>

#include <algorithm>
#include <cmath>

namespace mrolr::recog
{
/** Lines closer to parallel than this (rad) are related by perpendicular distance only. */
constexpr double kParallelAngle = 15.0 * M_PI / 180.0;

/** The relation of feature b seen from feature a. Field meaning depends on the kinds:
 * - line–line: h signed distance (or perpendicular distance if `parallel`), q1/q2 signed distance
 *   from each midpoint to the closest-approach point along its line (paper's q), [lo1, hi1] and
 *   [lo2, hi2] the endpoints relative to that point (-s, -t of the paper).
 * - line–conic (either order): h centre-to-line distance, [lo1, hi1] the line's endpoints relative
 *   to the foot of the perpendicular from the centre, ax1 the foot's offset along the normal.
 * - conic–conic: h centre distance, ax1 = (c2 - c1)·n1, ax2 = (c1 - c2)·n2. */
struct PairRelation
{
	double alpha = 0;
	double cos_alpha = 1, sin_alpha = 0;
	bool parallel = false;
	double h = 0;
	double q1 = 0, q2 = 0;
	double lo1 = 0, hi1 = 0, lo2 = 0, hi2 = 0;
	double ax1 = 0, ax2 = 0;
};

/** Position error beta (mm) and rotation error theta (rad) allowed on each feature (6.3.1). */
struct Tolerance
{
	Tolerance() : Tolerance(3, 0.035) {}
	Tolerance(double beta, double theta)
	    : beta_mm(beta),
	      theta_rad(theta),
	      tan_theta(std::tan(theta)),
	      cos_2theta(std::cos(2 * theta)),
	      sin_2theta(std::sin(2 * theta))
	{
	}
	double beta_mm;
	double theta_rad;
	double tan_theta, cos_2theta, sin_2theta;  ///< precomputed: the matcher's inner loop
};

/** Relation of @p b seen from @p a; @p parallel selects the near-parallel form for line pairs
 * (the model's relation decides it, so that model and scene are compared in the same form). */
PairRelation relate(const Feature& a, const Feature& b, bool parallel);

/** Relation of a model pair; the parallel form is chosen by kParallelAngle. */
PairRelation relateModel(const Feature& a, const Feature& b);

/** The cosines of the scene pair angles within 2·theta of the model pair @p m's angle alpha
 * (consistent()'s first test, through cosines: no acos in the matcher's inner loop). */
struct CosineRange
{
	double lo = -1, hi = 1;
	bool contains(double cos_s) const { return cos_s >= lo - 1e-12 && cos_s <= hi + 1e-12; }
};
CosineRange cosineRange(const PairRelation& m, const Tolerance& t);

/** consistent()'s tolerance for two skew model lines @p m (paper 3.2) on the common
 * perpendicular's length h, at tolerance @p t (mm). */
inline double skewHTolerance_mm(const PairRelation& m, const Tolerance& t)
{
	return 2 * t.beta_mm + (std::abs(m.q1) + std::abs(m.q2)) * t.tan_theta;
}
/** consistent()'s tolerances for two skew model lines on the intervals of the first and second
 * segment from the common perpendicular's feet. */
struct SkewIntervalTolerances
{
	double first_mm, second_mm;
};
/** The SkewIntervalTolerances of the skew model pair @p m at tolerance @p t. */
inline SkewIntervalTolerances skewIntervalTolerances(const PairRelation& m, const Tolerance& t)
{
	const double tanT = t.tan_theta, b2 = 2 * t.beta_mm;
	const double sinA = std::max(m.sin_alpha, 1e-3);
	return {b2 + std::abs(m.q2) * tanT / sinA, b2 + std::abs(m.q1) * tanT / sinA};
}

/** True when the scene pair (sa, sb) — oriented as hypothesised — lies within the error intervals
 * of the model relation @p m of the pair (ma, mb): orientation within 2·theta, distances within the
 * paper's bounds beta1 + beta2 + |q| tan(theta) (/ sin alpha for positions along the lines), and
 * each scene segment inside its model segment's interval (scene lines may be fragments). */
bool consistent(const PairRelation& m, const Feature& ma, const Feature& mb, const Feature& sa,
                const Feature& sb, const Tolerance& tol);
/** The same with the model pair's cosineRange(m, tol) given: a caller that asks it of many scene
 * pairs for one model pair works the range out once. */
bool consistent(const PairRelation& m, const CosineRange& angle, const Feature& ma,
                const Feature& mb, const Feature& sa, const Feature& sb, const Tolerance& tol);

}  // namespace mrolr::recog
