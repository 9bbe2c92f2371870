#pragma once
/** Obstacle mode of the mission (thesis 5.8.1.2, fig 5.8.1.4). Before a translation step the head
 * tilts down (pan 0, tilt_deg) and grabs a stereo pair (unless a clear look from about the same
 * heading still covers the step); ObstacleStereo turns it into points
 * above the floor in the base frame B. An obstacle within range_m ahead in the robot's corridor
 * (and not beyond the leg's goal) makes the head look left and right (±side_pan_deg) for free
 * space, and two waypoints round the obstacle on the free side are inserted (ObstacleDetour.h).
 * The waypoints are returned in W (z, x) from the robot's current estimate. */
#include <mrolr/hw/Devices.h>
#include <mrolr/mission/ObstacleDetour.h>
#include <mrolr/mission/SelfModel.h>
#include <mrolr/mission/ObstacleStereo.h>
#include <mrolr/mission/Timeline.h>
#include <mrolr/mission/Plan.h>

#include <nlohmann/json_fwd.hpp>

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace mrolr::mission
{
/** One look ahead that found an obstacle, and what was done about it. */
struct ObstacleEvent
{
	double time_s = 0;                                      ///< simulated time of the look
	Eigen::Vector3d xv_estimate = Eigen::Vector3d::Zero();  ///< (z, x, φ) in W when it looked
	ObstacleSighting sighting;                ///< B, metres, measured with the side looks too
	Detour detour;                            ///< B, metres
	std::vector<Eigen::Vector2d> via_zx_inW;  ///< the inserted waypoints, W
};

/** What obstacle mode did in one mission. */
struct ObstacleReport
{
	int looks = 0;         ///< stereo pairs grabbed (ahead and to the sides)
	int checks = 0;        ///< looks ahead before translation steps
	int failed_looks = 0;  ///< grabs or matchings that failed (the step went ahead unchecked)
	std::vector<ObstacleEvent> events;
};

class ObstacleAvoidance
{
 public:
	/** @p grab moves the head to the angles and grabs a stereo pair (simulated or real head). */
	using Grab = std::function<hw::StereoImages(const geometry::HeadAngles&)>;
	ObstacleAvoidance(const geometry::BiSightHead& head, const ObstacleOptions& options, Grab grab,
	                  Timeline& timeline);

	/** The check before a translation step from @p xv_estimate (z, x, φ in W) towards @p goal:
	 * the waypoints (W, (z, x)) to drive through first, empty when the way is clear. */
	std::vector<Eigen::Vector2d> check(const Eigen::Vector3d& xv_estimate,
	                                   const Eigen::Vector3d& goal);

	/** Head angles of a look at pan @p pan_deg: tilted by tilt_deg, verged at fixation_distance_m
	 * along the gaze. */
	geometry::HeadAngles lookAngles(double pan_deg) const;

	const ObstacleReport& report() const { return report_; }

	/** Tables of the map (W): points within @p margin_m of their footprints are no obstacles (the
	 * route planning goes round them already, TableDetour.cpp). Placed from the estimate. */
	void setKnownTables(const std::vector<PlanTable>& tables, double margin_m);
	/** Points on the robot's own arm are no obstacles (@p self outlives this). */
	void ignoreSelf(const SelfModel& self) { self_ = &self; }

 private:
	std::vector<Eigen::Vector3d> look(double pan_deg);
	/** The side looks: e.sighting measured again with them, and e.detour. */
	void lookAround(ObstacleEvent& e, std::vector<Eigen::Vector3d> points);
	void note(const ObstacleEvent& e);

	geometry::BiSightHead head_;
	ObstacleOptions o_;
	Grab grab_;
	Timeline& timeline_;
	ObstacleStereo stereo_;
	ObstacleReport report_;
	std::vector<PlanTable> tables_;
	const SelfModel* self_ = nullptr;
	double table_margin_m_ = 0;
	Eigen::Vector3d xv_ = Eigen::Vector3d::Zero();  ///< estimate at the current check
	bool onKnownTable(const Eigen::Vector3d& p_inB) const;
	/** True when the last clear look ahead still covers a step from @p xv. */
	bool coveredByLastLook(const Eigen::Vector3d& xv) const;
	std::optional<Eigen::Vector3d> last_clear_;  ///< where the last clear look was made
	double last_clear_length_m_ = 0;           ///< how far ahead it was clear
};

class Navigator;
struct MissionOptions;

/** Obstacle mode on @p nav: before its translations the look of @p avoidance (which must outlive
 * @p nav's driving) is asked; the plan's tables are no obstacles. */
void attachObstacleAvoidance(Navigator& nav, ObstacleAvoidance& avoidance, const MissionOptions& o);

/** report.json's "obstacle" block: looks, checks, failed looks and every obstacle seen (B, m) with
 * its side and inserted waypoints (W, m). */
nlohmann::json obstacleJson(const ObstacleReport& r);

/** The point (z, x) in W of a point (z, x) in the base frame of a vehicle at @p xv (z, x, φ). */
Eigen::Vector2d baseToWorld(const Eigen::Vector3d& xv, const Eigen::Vector2d& p_zx_inB);

}  // namespace mrolr::mission
