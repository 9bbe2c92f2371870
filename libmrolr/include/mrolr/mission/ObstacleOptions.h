#pragma once
/** Section [obstacle] of a mission file: obstacle mode (thesis 5.8.1.2, fig 5.8.1.4). Before each
 * translation step the head tilts down and a stereo pair is matched; an obstacle within range_m
 * ahead in the robot's corridor makes the robot look left and right for free space and insert
 * waypoints round the obstacle on the free side. Lengths in metres in the base frame B (on the
 * floor under the head centre C0, axes as C0: x left, y up, z forward). */
#include <mrpt/config/CConfigFileBase.h>

#include <iosfwd>
#include <string>

namespace mrolr::mission
{
struct ObstacleOptions
{
	// Read from the mission file: the robot's geometry and the thesis's range.
	double tilt_deg = -35;  ///< head tilt while looking ahead (negative: down)
	double range_m = 1.0;   ///< an obstacle nearer than this ahead is avoided (5.8.1.2: "1 metre")
	/** Half the robot's width plus a margin: the robot is a disc of this radius sweeping the
	 * corridor to its goal (the base is 0.70 m wide: 0.35 m + 5 cm). */
	double corridor_half_width_m = 0.40;

	// Fixed in code (docs/config.md "Fixed in code"): each value and why. "Set on the obstacle
	// lab" means chosen while building obstacle mode on maps/lab_obstacle (docs/mission.md).
	double fixation_distance_m = 1.5;  ///< verge here: inside the matcher's 0.4–3 m depths
	double side_pan_deg = 35;  ///< looks left/right: at range_m they see tan 35° = 0.7 m aside,
	                           ///< past the corridor and the clearance (0.65 m)
	double clearance_m = 0.25;  ///< kept from the obstacle when passing it; set on the obstacle lab
	double min_height_m = 0.06;  ///< points higher above the floor belong to obstacles (above the
	                             ///< matcher's floor noise; set on the obstacle lab) …
	double max_height_m = 1.2;   ///< … up to this height (the robot passes under higher ones)
	int min_points = 150;        ///< corridor points that make an obstacle; set on the obstacle lab
	int min_bin_points = 40;     ///< points that make a 5 cm lateral bin occupied; set likewise
	double assumed_depth_m = 0.4;  ///< depth of an obstacle whose top is not seen (a lab box)
	double image_scale = 0.35;     ///< disparities on images scaled by this (cost); set likewise
	double min_depth_m = 0.4;      ///< depth range searched by the matcher (optic axis): nearer is
	double max_depth_m = 3.0;      ///< under the base's front, farther is past two looks
	int block_size_px = 5;         ///< matcher block (odd, at image_scale); set likewise
	double min_texture_grey = 6;   ///< blocks with a smaller grey-level deviation are not used:
	                               ///< the matcher carries an edge's disparity into a plain floor
	double max_disparity_gradient = 1.0;  ///< px per px (at image_scale): steeper is a depth edge
	                                      ///< ("flying pixels" strung along the rays)
	double look_time_s = 2.0;             ///< simulated time of one look (tilt, grab, matching)
	double table_margin_m = 0.2;  ///< the map's tables grown by this are no obstacles: the route
	                              ///< goes round them already
	int max_detours_per_leg = 3;  ///< detours inserted on one leg before it is driven as planned

	/** Reads the three keys of @p section (all required); errors name file, section and key. */
	void loadFromConfigFile(const mrpt::config::CConfigFileBase& cfg, const std::string& section);
	void dump(std::ostream& out) const;
};

}  // namespace mrolr::mission
