#pragma once
/** The robot's plan of a place, `maps/<world>/plan.ini`: what a user tells a real robot about it,
 * as the thesis's waypoint browser (5.6.3) and known-feature files (5.6.2) did. It holds the route
 * (waypoints z x φ), the search stations and home; the known features (position in W with its
 * standard deviations, and the saved patch); and the footprints and heights of the tables the
 * robot drives round and grasps from, measured once by the user; optionally the room's walls, as
 * the floor's rectangle on a floor plan. Nothing of the objects on the tables and nothing of the
 * obstacles: those the robot must see. `mrolr-map` makes a plan from a
 * drive (docs/mission.md "Plan and map"). W: x left, y up, z forward, metres; φ from z towards x.
 *
 * ```
 * [plan]
 * route = W0 W1 W2        # driven in order before searching; the first is the start pose
 * stations = W5           # search stations in order
 * home = W6
 * [waypoints]
 * W0 = 0 0 0              # z_m x_m phi_deg
 * [known_features]
 * fire_sign = 1.0 1.6 5.99 patches/fire_sign.png 0.004 0.004 0.02   # X Y Z PNG σX σY σZ
 * [known_feature_views]   # optional
 * fire_sign = 0.0 1.0 0.0  # the head centre the patch was saved from, X Y Z
 * [room]                   # optional: the walls, the floor's corners (x z, m)
 * min_m = -3 -2
 * max_m = 3 6
 * [table.main]
 * centre_m = 0.0 1.5      # x z
 * yaw_deg = 0
 * size_m = 1.6 0.9 0.75   # length (along its x), depth (along its z), top height
 * ```
 */
#include <mrolr/util/IniDocument.h>

#include <Eigen/Core>
#include <opencv2/core.hpp>

#include <array>
#include <optional>
#include <string>
#include <vector>

namespace mrolr::mission
{
/** A named vehicle pose (z, x in m, φ in rad) in W: a waypoint, a station or home. */
struct NamedPose
{
	std::string name;
	Eigen::Vector3d xv_zxphi = Eigen::Vector3d::Zero();
};

/** A table's footprint and top height (W, m; yaw in degrees from W's z towards x). */
struct PlanTable
{
	std::string name;
	double x_m = 0, z_m = 0;  ///< centre of the top
	double yaw_deg = 0;
	double length_m = 0;  ///< along the table's own x
	double depth_m = 0;   ///< along the table's own z
	double top_height_m = 0;
};

/** The floor between the room's walls (W, m): a rectangle along W's axes. */
struct PlanRoom
{
	double min_x_m = 0, min_z_m = 0, max_x_m = 0, max_z_m = 0;
	/** Distance from @p p_zx to the nearest wall (negative outside the room). */
	double wallDistance(const Eigen::Vector2d& p_zx) const;
};

/** A known feature (5.6.2): where the robot mapped it, how well, and the patch it saved. */
struct PlanFeature
{
	std::string id;
	Eigen::Vector3d p_FinW = Eigen::Vector3d::Zero();   ///< m
	Eigen::Vector3d sigma_m = Eigen::Vector3d::Zero();  ///< standard deviations of X, Y, Z
	std::string patch_file;                             ///< as written in the plan
	cv::Mat patch;                                      ///< 8-bit grey
	/** Optional, `[known_feature_views] id = X Y Z`: the head centre in W the patch was saved
	 * from (thesis 5.6.2 stores "the robot's position" with a known feature); the 5.2.1
	 * visibility rules refer to it. Absent: the start pose's head centre. */
	std::optional<Eigen::Vector3d> p_viewinW;
};

/** `--set plan.SECTION.KEY=VALUE` (or `plan.KEY=VALUE` for [plan]): one override. */
using PlanOverride = std::array<std::string, 3>;  ///< section, key, value

struct Plan
{
	std::string path;  ///< the file it was read from
	std::vector<NamedPose> waypoints;
	std::vector<NamedPose> route;     ///< the first is the start pose
	std::vector<NamedPose> stations;  ///< at least one
	NamedPose home;
	std::vector<PlanFeature> known_features;
	std::vector<PlanTable> tables;
	std::optional<PlanRoom> room;  ///< [room], if the user gave the walls

	/** The waypoint called @p name, or nullptr. */
	const NamedPose* findWaypoint(const std::string& name) const;
	/** The start pose (the route's first waypoint). */
	const NamedPose& start() const { return route.front(); }

	/** Reads @p path with @p overrides applied; patches relative to its folder. Throws
	 * util::IniError naming file, line, section and key of the first problem. */
	static Plan load(const std::string& path, const std::vector<PlanOverride>& overrides = {});
	static Plan fromDocument(const util::IniDocument& doc);
	/** Writes the plan to @p file and each feature's patch PNG next to it (patch_file, relative
	 * to the plan's folder). */
	void save(const std::string& file) const;
};

}  // namespace mrolr::mission
