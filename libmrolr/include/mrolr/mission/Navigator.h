#pragma once
/** Waypoint navigation of the mission (thesis 5.6.3, 7.2.1): rotate–translate–rotate legs in 20 cm
 * steps on the base device, localised either by active-vision EKF-SLAM on the world's landmarks or
 * by dead reckoning. The simulated head measures the ideal-head angles (eq 5.40) of visible
 * landmarks with Gaussian noise (not image-based vision); legs are repeated from the new estimate
 * until it is within waypoint_tolerance_m. Straight legs that would cross a table go round it. */
#include <mrolr/hw/Devices.h>
#include <mrolr/mission/MissionOptions.h>
#include <mrolr/mission/Timeline.h>
#include <mrolr/slam/ActiveSlamFilter.h>

#include <functional>
#include <memory>
#include <random>

namespace mrolr::mission
{
/** One sample of the path after a motion step: poses (z, x, φ) in W. */
struct PathSample
{
	double time_s = 0;
	Eigen::Vector3d truth, estimate, odometry;
	Eigen::Matrix3d P_vv = Eigen::Matrix3d::Zero();
	int features = 0;
	long ticks_right = 0, ticks_left = 0;
};

/** A mapped landmark at the end: label, position in W (m) and covariance (m²). */
struct MappedLandmark
{
	std::string label;
	Eigen::Vector3d p_FinW;
	Eigen::Matrix3d P;
};

class Navigator
{
 public:
	/** @p truth: the true vehicle pose (for the simulated head's measurements only). */
	Navigator(const MissionOptions& o, hw::BaseDevice& base, std::function<Eigen::Vector3d()> truth,
	          Timeline& timeline);
	/** Drives to @p goal (z, x, φ in W), going round tables in the way. */
	void driveTo(const NamedPose& goal);
	/** The current estimate (SLAM or odometry). */
	Eigen::Vector3d estimate();
	const std::vector<PathSample>& path() const { return path_; }
	std::vector<MappedLandmark> map();
	/** Called after every step with the sample just recorded (progress, rawlog). */
	std::function<void(const PathSample&)> on_step;
	/** Obstacle mode (thesis 5.8.1.2, ObstacleAvoidance.h): called before every translation step
	 * with the estimate and the leg's goal (z, x, φ in W); returns waypoints (z, x in W) to drive
	 * through first, empty when the way is clear. Unset: no checks. */
	std::function<std::vector<Eigen::Vector2d>(const Eigen::Vector3d& estimate,
	                                           const Eigen::Vector3d& goal)>
	    before_translation;
	int max_detours_per_leg = 3;  ///< detours on one leg before the rest is driven unchecked
	int measurements = 0, rejected = 0;

 private:
	/** Drives through @p via (z, x in W), arriving at each in the direction of travel. */
	void driveThrough(const std::vector<Eigen::Vector2d>& via, Eigen::Vector2d from,
	                  int correction_legs);
	/** Rotate–translate–rotate to @p goal, repeated up to @p correction_legs times. */
	void driveStraightTo(const Eigen::Vector3d& goal, int correction_legs);
	/** Executes @p plan; false when a detour was driven instead of the rest of it. */
	bool executeLeg(const std::vector<base::PlannedStep>& plan, const Eigen::Vector3d& goal,
	                int& detours);
	void execute(const base::PlannedStep& step);
	void measure();
	std::vector<size_t> visibleMapped(const Eigen::Vector3d& xv_true);
	void initialiseNewFeature(const Eigen::Vector3d& xv_true);
	bool canSee(const Eigen::Vector3d& xv_true, const world::Landmark& l) const;
	Eigen::Vector3d noisyMeasurement(const Eigen::Vector3d& xv_true, const Eigen::Vector3d& p);
	void record();

	const MissionOptions& o_;
	hw::BaseDevice& base_;
	std::function<Eigen::Vector3d()> truth_;
	Timeline& timeline_;
	base::LabmateModel model_;
	slam::ActiveSlamFilter filter_;
	std::mt19937 rng_;
	std::vector<PathSample> path_;
	int detour_depth_ = 0;  ///< detours being driven inside detours
};

/** Via points that take the straight path from @p from to @p to (z, x in W) round every table of
 * @p w it would cross, keeping @p clearance_m from the table's edges; empty when the path is
 * clear. */
std::vector<Eigen::Vector2d> detourAroundTables(const world::World& w, const Eigen::Vector2d& from,
                                                const Eigen::Vector2d& to, double clearance_m);

}  // namespace mrolr::mission
