#pragma once
/** Waypoint navigation of the mission (thesis 5.6.3, 7.2.1): rotate–translate–rotate legs in 20 cm
 * steps on the base device, localised either by active-vision EKF-SLAM on the world's landmarks or
 * by dead reckoning. The head measures either the ideal-head angles (eq 5.40) of the world's
 * visible landmarks with Gaussian noise (`ideal`), or features it acquires and finds again in its
 * stereo pairs through the vision area (`images`, useImages()); legs are repeated from the new
 * estimate until it is within waypoint_tolerance_m. Straight legs that would cross a table go round
 * it. */
#include <mrolr/hw/Devices.h>
#include <mrolr/mission/MissionOptions.h>
#include <mrolr/mission/Timeline.h>
#include <mrolr/slam/ActiveSlamFilter.h>
#include <mrolr/vision/VisualSlam.h>

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
	/** measurement_source = images: from now on every step's measurements are made by
	 * vision::VisualSlam on the pairs of @p head (features of its own, no world landmarks; the
	 * grabbing time goes to the timeline's render time, the rest to compute). */
	void useImages(vision::StereoHeadDevice& head, const std::function<double()>& grab_seconds);
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
	/** ideal: measurements lost (lost_feature_probability), features deleted by the 5.7 rule. */
	int lost = 0, deleted_features = 0;
	int image_cycles = 0, image_matched = 0;  ///< images: cycles that searched, matches found

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
	/** True (and the failed attempt recorded) when feature @p i is lost this time. */
	bool lostThisTime(size_t i);
	/** Deletes the features failing the 5.7 rule (known features are kept). */
	void deleteFailingFeatures();
	/** measurements_per_step cycles of the vision area (the first one predicts with @p u). */
	void measureInImages(const base::WheelControl& u);
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
	int detour_depth_ = 0;                       ///< detours being driven inside detours
	std::unique_ptr<vision::VisualSlam> vslam_;  ///< images: the vision area's cycle
	vision::StereoHeadDevice* images_head_ = nullptr;
	std::function<double()> grab_seconds_;
};

/** Rotate–translate–rotate from @p from to @p to (z, x, φ in W) as base::planLeg, except that a
 * goal behind the robot and at most @p reverse_max_m away is reached backwards: turn by less than
 * 90° to face directly away from it, back up in the planner's steps (negative distances), turn to
 * the goal's heading. */
std::vector<base::PlannedStep> planMissionLeg(const Eigen::Vector3d& from,
                                              const Eigen::Vector3d& to,
                                              const base::LabmateModel& model,
                                              const base::TrajectoryOptions& o,
                                              double reverse_max_m);

/** Via points that take the straight path from @p from to @p to (z, x in W) round every table of
 * @p w it would cross, keeping @p clearance_m from the table's edges; empty when the path is
 * clear. */
std::vector<Eigen::Vector2d> detourAroundTables(const world::World& w, const Eigen::Vector2d& from,
                                                const Eigen::Vector2d& to, double clearance_m);

}  // namespace mrolr::mission
