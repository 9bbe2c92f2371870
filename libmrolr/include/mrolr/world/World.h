#pragma once
/** The description of a simulated (or real) lab: `maps/<name>/world.ini`. The point-landmark part
 * (sections [landmarks] and [waypoints]) is the EKF-SLAM world of thesis 5.6 / simulator module 1
 * (6.8); docs/sim.md documents the whole format.
 *
 * All positions are in the world frame W of the thesis: x left, y up, z forward, metres, origin at
 * the base centre of the vehicle's start pose on the ground plane (C0 is head_height_m above it,
 * geometry::T_C0inW); vehicle headings φ turn from z towards x. */

#include <mrolr/world/WorldIni.h>
#include <mrolr/world/Scenery.h>

#include <Eigen/Core>

#include <string>
#include <vector>

namespace mrolr::world
{
/** A 3D point feature (thesis 5.4): position in W (m); known features (5.6.2) start with zero
 * covariance in the filter. */
struct Landmark
{
	std::string name;
	Eigen::Vector3d p_LinW = Eigen::Vector3d::Zero();
	bool known = false;
};

/** A vehicle pose of the route (thesis 5.6.3): z, x in W (m) and heading φ (rad, from z towards x;
 * given in degrees in the file). */
struct Waypoint
{
	std::string name;
	double z_m = 0;
	double x_m = 0;
	double phi_rad = 0;
};

/** A whole world file. */
struct World
{
	std::string path;                 ///< the file it was read from
	std::vector<Landmark> landmarks;  ///< [landmarks], in file order
	std::vector<Waypoint> waypoints;  ///< [waypoints], in file order (the route)
	bool has_room = false;            ///< false for a pure point-landmark world (no [room] section)
	Room room;                        ///< [room]
	std::vector<Patch> patches;       ///< [patch.NAME] sections; each also adds a Landmark NAME
	std::vector<Table> tables;        ///< [table.NAME]
	std::vector<Obstacle> obstacles;  ///< [obstacle.NAME]
	std::vector<PlacedObject> objects;  ///< [object.NAME]
	MissionSpec mission;                ///< [mission]
	std::string objects_dir;  ///< [room] objects_dir, resolved against the world file's folder

	/** Folder of the world file (for relative texture paths). */
	std::string directory() const;
	/** The table with this name, or nullptr. */
	const Table* findTable(const std::string& name) const;
	/** The placed object with this name, or nullptr. */
	const PlacedObject* findObject(const std::string& name) const;

	/** Reads a world file; throws WorldError naming file, line, section, key and value of the
	 * first malformed entry. */
	static World load(const std::string& path);
	/** Parses world text as if read from @p path (for tests and in-memory worlds). */
	static World parse(const std::string& text, const std::string& path = "<memory>");
	/** Builds a world from an already read document. */
	static World fromDocument(const IniDocument& doc);

	/** The landmark with this name, or nullptr. */
	const Landmark* findLandmark(const std::string& name) const;
	/** The waypoint with this name, or nullptr. */
	const Waypoint* findWaypoint(const std::string& name) const;
};

}  // namespace mrolr::world
