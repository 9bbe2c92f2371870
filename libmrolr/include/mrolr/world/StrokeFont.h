#pragma once
/** A small straight-stroke font for the letters printed on objects (the alphabet cube, thesis 6.1):
 * each letter is a list of segments in a unit box, x to the right in [0, 0.6], y up in [0, 1]. Only
 * straight strokes, so every stroke is an exact 3D line of the object's wire-frame. */

#include <Eigen/Core>

#include <utility>
#include <vector>

namespace mrolr::world
{
using Stroke = std::pair<Eigen::Vector2d, Eigen::Vector2d>;

/** Strokes of @p letter (upper case A–Z except the round letters; see hasStrokeLetter).
 * Throws std::invalid_argument for a letter the font does not have. */
std::vector<Stroke> strokeLetter(char letter);

/** True when strokeLetter knows @p letter. */
bool hasStrokeLetter(char letter);

}  // namespace mrolr::world
