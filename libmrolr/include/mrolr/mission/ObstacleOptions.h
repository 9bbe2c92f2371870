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
	double tilt_deg = -35;             ///< head tilt while looking ahead (negative: down)
	double fixation_distance_m = 1.5;  ///< verge on the point this far along the gaze
	double side_pan_deg = 35;          ///< pan of the looks left (+) and right (−) for free space
	double range_m = 1.0;              ///< an obstacle nearer than this ahead is avoided (5.8.1.2)
	/** Half the robot's width plus a margin: the robot is a disc of this radius sweeping the
	 * corridor to its goal. */
	double corridor_half_width_m = 0.40;
	double clearance_m = 0.10;     ///< kept between the corridor and the obstacle when passing it
	double min_height_m = 0.06;    ///< points higher above the floor belong to obstacles …
	double max_height_m = 1.2;     ///< … up to this height (the robot passes under higher ones)
	int min_points = 150;          ///< obstacle points in the corridor that make an obstacle
	int min_bin_points = 8;        ///< points in a 5 cm lateral bin that make it occupied
	double assumed_depth_m = 0.4;  ///< depth of an obstacle whose top is not seen
	double image_scale = 0.5;      ///< disparities are computed on images scaled by this
	double min_depth_m = 0.4;      ///< depth range searched by the matcher (optic axis)
	double max_depth_m = 3.0;
	int block_size_px = 5;        ///< matcher block (odd, at image_scale)
	double min_texture_grey = 6;  ///< blocks with a smaller grey-level deviation are not used
	double max_disparity_gradient = 1.0;  ///< px per px (at image_scale): steeper is a depth edge
	double look_time_s = 2.0;             ///< simulated time of one look (tilt, grab, matching)
	double table_margin_m = 0.2;          ///< the map's tables grown by this are no obstacles
	int max_detours_per_leg = 3;  ///< detours inserted on one leg before it is driven as planned

	/** Reads every key of @p section (all required); errors name file, section and key. */
	void loadFromConfigFile(const mrpt::config::CConfigFileBase& cfg, const std::string& section);
	void dump(std::ostream& out) const;
};

}  // namespace mrolr::mission
