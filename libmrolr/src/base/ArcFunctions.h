#pragma once
// sinθ/θ, (1 − cos θ)/θ and their derivatives, evaluated by Taylor series near θ = 0 so that the
// Labmate arc equations (5.4, 5.6) pass smoothly into the straight-line case (5.8, 5.9).

namespace mrolr::base::detail
{
struct ArcTerms
{
	double a;   ///< sinθ/θ
	double b;   ///< (1 − cos θ)/θ
	double da;  ///< d(sinθ/θ)/dθ
	double db;  ///< d((1 − cos θ)/θ)/dθ
};

/** All four terms at θ (radians); series below |θ| = 1e-2, closed forms above. */
ArcTerms arcTerms(double theta);

}  // namespace mrolr::base::detail
