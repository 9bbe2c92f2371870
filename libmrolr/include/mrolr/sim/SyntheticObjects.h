#pragma once
/** Wire-frame models of lab objects built in code (mm, object frame O with z up from the base
 * centre) for tests, benchmarks and demonstrations of recognition: exact geometry, so a model
 * carried by a known pose gives exact ground truth. */

#include <mrolr/model/WireFrame.h>

#include <string>
#include <vector>

namespace mrolr::sim
{
/** 60 mm alphabet cube: 12 edges and the letters A, E, F, H, K, T drawn in lines on its faces. */
model::WireFrame makeAlphabetCube();
/** Cup: top and bottom rims, a seam, a handle (two struts and an arc), a rim-height band arc. */
model::WireFrame makeCup();
/** Bottle: base, shoulder and neck circles, cap, a label rectangle and a seam. */
model::WireFrame makeBottle();
/** Drinks can: two rims, the label's upper and lower edges, a ring-pull line pair and a seam. */
model::WireFrame makeCan();
/** Stapler-like box 160 × 45 × 55 mm with a slot and a sloping top. */
model::WireFrame makeStaplerBox();
/** Book 210 × 150 × 30 mm with a title block on the cover. */
model::WireFrame makeBook();
/** Tea box 75 × 75 × 140 mm with a window on one face. */
model::WireFrame makeTeaBox();
/** Triangular wedge 120 × 60 × 50 mm with a groove on the slope. */
model::WireFrame makeWedge();
/** Tape roll: outer and inner circles top and bottom, two tape-end lines and a printed arc on
 * the top face (so that top and bottom differ). */
model::WireFrame makeTapeRoll();
/** L-shaped bracket 100 × 80 × 40 mm. */
model::WireFrame makeBracket();

/** The ten objects above, in that order (the "10-model database"). */
std::vector<model::WireFrame> makeLabObjects();

}  // namespace mrolr::sim
