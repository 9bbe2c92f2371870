#pragma once
/** Collisions of the Labmate base with the world (world side): the base's footprint, a rectangle on
 * the floor, against the room's walls (the footprint must stay inside the room box), every table's
 * top and every obstacle's footprint (rectangles with yaw, Scenery.h).
 *
 * Everything here is 2D on the floor of W, points as (z, x) in metres (z forward, x left) and
 * vehicle poses as (z, x, φ) with φ from z towards x, like base::LabmateModel. A motion is checked
 * at samples no further apart than kSampleStep_m at any point of the footprint, so a 20 cm step or a
 * 45° turn cannot jump through a 5 cm thick thing; the first contact is then bisected down to
 * kContactTolerance_m. Touching (zero overlap area) is free; overlapping is a contact. */

#include <mrolr/world/World.h>

#include <Eigen/Core>

#include <array>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace mrolr::sim
{
/** The base's outline on the floor: a rectangle `length_m` along the heading and `width_m` across
 * it, whose centre lies `offset_m` ahead of the wheel-axle centre (the vehicle pose's origin). */
struct Footprint
{
	double length_m = 0.8;  ///< along the heading (m)
	double width_m = 0.7;   ///< across the heading (m)
	double offset_m = 0.0;  ///< centre ahead of the axle centre (m; negative: behind)
};

/** The farthest any footprint point moves between two checked samples of a motion (m). */
constexpr double kSampleStep_m = 0.01;
/** How far (at most, at any footprint point) the last free pose lies before the contact (m). */
constexpr double kContactTolerance_m = 0.0005;

/** Something the footprint overlaps at one pose. */
struct Touch
{
	std::string what;  ///< `wall`, `table.<name>` or `obstacle.<name>`
	Eigen::Vector2d p_zx_m = Eigen::Vector2d::Zero();  ///< centroid of the overlap, W (z, x), m
};

/** The first contact along a motion. */
struct Contact
{
	std::string what;  ///< `wall`, `table.<name>` or `obstacle.<name>`
	Eigen::Vector2d p_zx_m = Eigen::Vector2d::Zero();  ///< contact point, W (z, x), m
	Eigen::Vector3d last_free_zxphi = Eigen::Vector3d::Zero();  ///< last free pose (z, x, φ), W
	double free_fraction = 0;  ///< the part of the motion done at the last free pose, 0..1
};

/** The nearest thing to the footprint at one pose. */
struct Clearance
{
	std::string what;       ///< as in Touch; empty in a world with nothing to hit
	double distance_m = 0;  ///< gap between the footprint and it; 0 when they overlap
};

/** A motion of the base: its pose (z, x, φ) in W at fraction t ∈ [0, 1] of the motion. */
using Motion = std::function<Eigen::Vector3d(double t)>;

/** The world's fixed bodies (walls, tables, obstacles) and the base's footprint. */
class CollisionWorld
{
 public:
	/** A convex outline on the floor, W (z, x), counter-clockwise seen from above (y up). */
	using Polygon = std::vector<Eigen::Vector2d>;

	/** Takes the room (if the world has one), the tables and the obstacles of @p world. */
	CollisionWorld(const world::World& world, const Footprint& footprint);

	const Footprint& footprint() const { return footprint_; }

	/** The footprint's four corners at pose (z, x, φ), grown by @p margin_m on every side. */
	Polygon footprintAt(const Eigen::Vector3d& pose_zxphi, double margin_m = 0) const;

	/** The first thing (walls, then tables, then obstacles, in file order) that the footprint,
	 * grown by @p margin_m, overlaps at the pose; nullopt when it is free. */
	std::optional<Touch> touchAt(const Eigen::Vector3d& pose_zxphi, double margin_m = 0) const;

	/** The nearest wall, table or obstacle to the footprint at the pose. */
	Clearance clearanceAt(const Eigen::Vector3d& pose_zxphi) const;

	/** The first contact along the straight motion from @p from to @p to: z, x and φ change
	 * linearly (φ is not wrapped: pass the heading the base turns through). nullopt: free. */
	std::optional<Contact> firstContact(const Eigen::Vector3d& from, const Eigen::Vector3d& to) const;

	/** The first contact along @p motion, which translates the axle centre by at most
	 * @p travel_m and turns by at most @p turn_rad (these bound how fast footprint points move,
	 * hence the sampling). A motion that starts overlapping stops at once (free_fraction 0). */
	std::optional<Contact> firstContact(const Motion& motion, double travel_m, double turn_rad) const;

	/** The farthest a footprint point lies from the axle centre (m). */
	double footprintRadius() const;

 private:
	struct Body
	{
		std::string what;
		Polygon outline;
	};
	std::optional<Touch> wallTouch(const Polygon& footprint) const;
	double wallGap(const Polygon& footprint) const;
	Contact bisect(const Motion& motion, double t_free, double t_hit, double sweep_m) const;

	Footprint footprint_;
	bool has_room_ = false;
	Eigen::Vector2d room_min_zx_, room_max_zx_;
	std::vector<Body> bodies_;  ///< tables, then obstacles
};

/** The outline of a rectangle centred at (z, x) in W with yaw (rad, from z towards x), @p along_x_m
 * along its own x and @p along_z_m along its own z (the Scenery.h convention). */
CollisionWorld::Polygon rectangleOnFloor(double z_m, double x_m, double yaw_rad, double along_x_m,
                                         double along_z_m);

}  // namespace mrolr::sim
