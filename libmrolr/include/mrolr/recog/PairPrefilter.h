#pragma once
/** A quick, conservative form of consistent() (PairRelation.h) for one scene feature against
 * many, on packed arrays so that the compiler vectorises it (MROLR_SIMD_CLONES): the angle test
 * and, for two skew model lines, the tests of their common perpendicular's length h and of the
 * intervals of the two segments from its feet (paper 3.2), each widened by far more than rounding
 * can move them. It never rejects a pair that consistent() accepts; consistent() then decides for
 * those it keeps. Most scene pairs fail one of these tests (MemberCandidates::of). */

#include <mrolr/recog/Feature.h>
#include <mrolr/recog/PairRelation.h>

#include <cstdint>
#include <vector>

namespace mrolr::recog
{
/** Directions, midpoints and lengths of scene features, one array per coordinate. */
struct PackedFeatures
{
	std::vector<double> ux, uy, uz, mx, my, mz, len;
	void push_back(const Feature& f);
	size_t size() const { return ux.size(); }
	/** The arrays' data, as the vectorised test reads them. */
	struct Arrays
	{
		const double *ux, *uy, *uz, *mx, *my, *mz, *len;
	};
	Arrays arrays() const;
};

/** keep[k] = 0 for the features @p b of @p packed that cannot be consistent() with the model pair
 * (@p ma, @p mb) of relation @p m under @p tol when @p a is matched to ma, 1 for the others.
 * @p keep is resized to packed.size(). */
void mayBeConsistent(const PairRelation& m, const Feature& ma, const Feature& mb, const Feature& a,
                     const PackedFeatures& packed, const Tolerance& tol,
                     std::vector<std::int64_t>& keep);

}  // namespace mrolr::recog
