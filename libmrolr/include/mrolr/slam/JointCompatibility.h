#pragma once
/** Joint compatibility of several measurements made from the same state (Neira & Tardós 2001,
 * "Data association in stochastic mapping using the joint compatibility test"): one step's matches
 * of distinct mapped features are accepted together only if their stacked innovation passes the
 * χ² gate of its dimension, ν_Jᵀ S_J⁻¹ ν_J ≤ χ²_{3k}(p) with S_J = H_J P H_Jᵀ + R_J (the
 * cross-covariances between the features' predictions included). Each feature has one candidate
 * (its best patch match), so the search is over subsets: branch and bound finds the largest
 * jointly compatible subset, the lower joint NIS breaking ties. A wrong match that passes its own
 * gate but contradicts the others is left out, so it cannot corrupt the map. */
#include <mrolr/slam/ActiveSlamFilter.h>

#include <vector>

namespace mrolr::slam
{
struct JointCompatibility
{
	std::vector<size_t> accepted;  ///< indices into the candidates, ascending
	double joint_nis = 0;          ///< of the accepted subset
};

/** The largest jointly compatible subset of @p candidates (distinct features) at the filter's
 * current estimate, with the gate probability @p gate_probability. */
JointCompatibility jointlyCompatible(ActiveSlamFilter& filter,
                                     const std::vector<Observation>& candidates,
                                     double gate_probability);

}  // namespace mrolr::slam
