#pragma once
/** The geometry of obstacle mode (thesis 5.8.1.2, fig 5.8.1.4) on points above the floor in the
 * base frame B (x left, y up, z forward, metres; ObstacleStereo.h): is there an obstacle in the
 * robot's corridor within range, how wide and deep is it, and on which side is there space to
 * pass it. The inserted waypoints go round the obstacle on the free side: beside its near corner,
 * then beside its far corner, each corridor_half_width_m + clearance_m from it. */
#include <mrolr/mission/ObstacleOptions.h>

#include <Eigen/Core>

#include <vector>

namespace mrolr::mission
{
/** An obstacle ahead (B, metres). */
struct ObstacleSighting
{
	bool blocked = false;  ///< at least min_points obstacle points in the corridor
	int points = 0;        ///< obstacle points in the corridor
	double near_m = 0;     ///< nearest obstacle distance ahead (B z)
	double far_m = 0;      ///< its far edge: seen, or near_m + assumed_depth_m if further
	double left_m = 0;     ///< its extent across the route: largest B x (left) …
	double right_m = 0;    ///< … and smallest B x (right)
};

/** Points of the corridor |x| ≤ corridor_half_width_m, 0 < z ≤ @p corridor_length_m, and with
 * @p goal_at_end also those within corridor_half_width_m of its end (the robot, a disc of that
 * radius, standing at the goal: the area it sweeps). When there are
 * at least min_points, the sighting is blocked and its extent is measured: the occupied 5 cm
 * lateral bins (min_bin_points) next to the corridor's, between near_m and near_m + range_m. */
ObstacleSighting obstacleAhead(const std::vector<Eigen::Vector3d>& p_inB, double corridor_length_m,
                               const ObstacleOptions& o, bool goal_at_end = false);

/** Side to pass on and the waypoints to insert (B, (z, x) metres). */
struct Detour
{
	int side = 0;                           ///< +1: left of the obstacle (B +x), −1: right
	bool both_blocked = false;              ///< neither side was free: the emptier one was taken
	int points_left = 0, points_right = 0;  ///< obstacle points in each side's passage
	std::vector<Eigen::Vector2d> via_zx;    ///< beside the near corner, beside the far corner
};

/** The passage on each side is the robot's corridor along the inserted waypoints, from the robot
 * to beyond the far edge; a side is free with fewer than min_points points of @p p_inB in it
 * (these include the side looks). The free side needing the smaller sideways move wins. */
Detour planDetour(const ObstacleSighting& s, const std::vector<Eigen::Vector3d>& p_inB,
                  const ObstacleOptions& o);

}  // namespace mrolr::mission
