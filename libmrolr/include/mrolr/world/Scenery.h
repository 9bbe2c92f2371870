#pragma once
/** The visible parts of a world file beyond point landmarks (docs/sim.md "World format"): the room,
 * textured landmark patches, tables, obstacles, objects on tables and the fetch mission. All
 * positions are in W (x left, y up, z forward, metres); headings/yaws turn about W's y axis from z
 * towards x, like the vehicle heading φ. */

#include <Eigen/Core>

#include <string>
#include <vector>

namespace mrolr::world
{
/** The room: an axis-aligned box in W and the textures of its surfaces (texture specs: a path
 * relative to the world file, or `procedural:<pattern>`; see Textures.h). */
struct Room
{
	Eigen::Vector3d min_m{-3.0, 0.0, -2.0};  ///< corner with the smallest x, y (floor), z
	Eigen::Vector3d max_m{3.0, 3.0, 6.0};    ///< corner with the largest x, y (ceiling), z
	std::string wall_texture = "procedural:wall";
	std::string floor_texture = "procedural:floor";
	std::string ceiling_texture = "procedural:ceiling";
	double floorY() const { return min_m.y(); }
};

/** A textured planar landmark (a poster, sign or light fitting). Its centre is also a point
 * landmark (thesis 5.4) of the same name; `known` marks a known feature (5.6.2). The texture's "up"
 * edge points along `up`, and the texture is seen from the side the normal points to. */
struct Patch
{
	std::string name;
	Eigen::Vector3d centre_m = Eigen::Vector3d::Zero();  ///< W
	Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();   ///< unit, towards the viewer, W
	Eigen::Vector3d up = Eigen::Vector3d::UnitY();       ///< unit, in the plane, W
	double width_m = 0.3;
	double height_m = 0.3;
	std::string texture;  ///< texture spec
	bool known = false;
};

/** A table: a dark top (thesis 7.2.2) on four legs, standing on the floor. */
struct Table
{
	std::string name;
	double x_m = 0, z_m = 1.5;   ///< centre of the top, W
	double yaw_deg = 0;          ///< about the vertical (W y), from W's z towards x
	double length_m = 1.2;       ///< along the table's own x
	double depth_m = 0.8;        ///< along the table's own z
	double top_height_m = 0.75;  ///< top surface above the floor
	Eigen::Vector3d top_colour{0.12, 0.12, 0.13};  ///< RGB 0..1, dark and non-reflective
};

/** A box obstacle standing on the floor. */
struct Obstacle
{
	std::string name;
	double x_m = 0, z_m = 0, yaw_deg = 0;   ///< centre of the footprint, W
	Eigen::Vector3d size_m{0.5, 1.0, 0.5};  ///< along its x, height, along its z
	Eigen::Vector3d colour{0.5, 0.5, 0.55};
	/** Texture spec of its four sides and top (a printed carton: something stereo can match);
	 * empty: plain `colour`. */
	std::string texture;
};

/** An object of the database placed on a table: its model frame O (z up, thesis 6.1) stands on the
 * table top at (x, z) in W, rotated by yaw about the vertical. */
struct PlacedObject
{
	std::string name;         ///< instance name (section name)
	std::string model;        ///< object definition datasets/objects/<model>.ini
	std::string table;        ///< the table it stands on
	double x_m = 0, z_m = 0;  ///< W
	double yaw_deg = 0;       ///< about the vertical, from W's z towards x
};

/** The fetch mission of the world (thesis 7.2). */
struct MissionSpec
{
	std::string target;          ///< PlacedObject name to fetch ("" when there is no mission)
	std::string table_waypoint;  ///< waypoint from which the table is searched
	std::string home_waypoint;   ///< waypoint to return to
};

}  // namespace mrolr::world
