#pragma once
/** Which model explains a place better: a target answer is doubtful when another model of the
 * database is found at the same place with a higher image score. Two objects cannot stand on
 * the same spot of a table, so one of the two answers is wrong; the image score (the fraction of
 * the expected-visible model edge samples on image edges, ImageVerifier) is what both were
 * accepted by. The thesis recognises one requested object at a time (thesis 6.4); this is the
 * check a database search adds. */
#include <mrolr/model/WireFrame.h>
#include <mrolr/recog/Recognizer.h>

#include <Eigen/Core>
#include <optional>
#include <vector>

namespace mrolr::recog
{
/** A model's footprint on its support, in its own frame O (mm): O's +z is the model's up. */
struct Footprint
{
	Eigen::Vector3d centre_O = Eigen::Vector3d::Zero();  ///< the middle of its bounding box
	double radius_mm = 0;  ///< largest distance across +z of a model point from centre_O
};

/** The footprint of @p wf (its lines' ends and its conics' arcs). */
Footprint footprintOf(const model::WireFrame& wf);

/** A found answer and its model's footprint. */
struct PlacedAnswer
{
	const RecognitionResult* result = nullptr;
	Footprint footprint;
};

/** The index in @p rivals of the found rival that takes @p target's place with a higher image
 * score, the highest if several; none if there is none, or if @p target is not found or has no
 * image score. Two answers take the same place when, measured across @p up_S (the scene's up,
 * unit), the centre of one lies within the larger of the two footprint radii of the other's. */
std::optional<size_t> betterExplained(const PlacedAnswer& target,
                                      const std::vector<PlacedAnswer>& rivals,
                                      const Eigen::Vector3d& up_S);

}  // namespace mrolr::recog
