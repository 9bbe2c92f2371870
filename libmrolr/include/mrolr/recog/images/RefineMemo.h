#pragma once
// What the image refinements of one search have swept and searched, for the next ones.
#include <mrolr/recog/images/ImageVerifier.h>

#include <Eigen/Geometry>

#include <vector>

namespace mrolr::recog
{
/** The yaw sweep of ImageVerifier::refine about one axis: every yaw of the circle of poses
 * T · Rz(yaw) about the axis through the model point a_O, yaw 0 (T itself) included: the one with
 * the most supported samples (then the lowest cost) and the one with the highest supported
 * fraction. */
struct SweptCircle
{
	ScoredPose by_count, by_fraction;
};

/** What the refinements of one search (ImageVerifier::refine with a memo) have done, so that the
 * next ones do not do it again:
 * - the circles swept: a start on a circle already swept about the same axis (its axis point and
 *   up axis within 0.1 mm and 0.1°, its yaw a whole number of sweep steps away; the plane
 *   hypotheses of one rim come 30° apart) would sweep the same poses, and takes that circle's;
 * - the local searches (edgeLineSearch) made, by their seed pose and axis: the same seed gives
 *   the same result. */
struct RefineMemo
{
	struct Circle
	{
		size_t axis;          ///< index into the axes refine() was given
		Eigen::Isometry3d T;  ///< the start it was swept from
		SweptCircle swept;
	};
	struct Search
	{
		Eigen::Isometry3d seed;
		Eigen::Vector3d axis_O;
		ScoredPose result;
	};
	std::vector<Circle> circles;
	std::vector<Search> searches;
	int circles_reused = 0;  ///< circles taken from circles instead of swept
};

}  // namespace mrolr::recog
