#pragma once
/** Collision tests between the RTX's body boxes (arm/ArmBody.h), the robot's own deck and mast, and
 * the arm itself: exact overlap of oriented boxes by the separating axis theorem (Gottschalk, Lin &
 * Manocha 1996, OBBTree: two convex boxes are apart iff one of the 15 axes — the 3 face normals of
 * each and the 9 cross products of their edges — separates their projections). Lengths in mm. */

#include <mrolr/arm/ArmBody.h>

#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace mrolr::arm
{
/** True when @p a and @p b, each grown by @p margin_mm on every face, overlap. */
bool boxesOverlap(const PlacedBox& a, const PlacedBox& b, double margin_mm);

/** The pairs of @p body's boxes (same order as its placed boxes) that must never meet: boxes of
 * chain frames at least two links apart, beyond the joints that join neighbours (the column and
 * the carriage hold the upper arm at the shoulder; the forearm carries the wrist). */
std::vector<std::pair<size_t, size_t>> selfCollisionPairs(const std::vector<BodyBox>& body);

/** The first pair of @p pairs whose boxes of @p placed meet (grown by @p margin_mm), if any. */
std::optional<std::pair<size_t, size_t>> firstSelfContact(
    const std::vector<PlacedBox>& placed, const std::vector<std::pair<size_t, size_t>>& pairs,
    double margin_mm);

/** The open finger plates and the room between them as one box of frame 6 (G), for the
 * tests that must include the fingers; it follows rtxBody()'s boxes as box 8. */
BodyBox fingerBox(const GraspFeasibilityOptions& grip, double finger_thickness_mm);

/** A readable name of box @p i of rtxBody() followed by fingerBox() ("column", "fingers", …). */
std::string bodyBoxName(size_t i);

}  // namespace mrolr::arm
