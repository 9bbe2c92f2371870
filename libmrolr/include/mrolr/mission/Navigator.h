#pragma once
/** Waypoint navigation of the mission (thesis 5.6.3, 7.2.1): rotate–translate–rotate legs in 20 cm
 * steps on the base device, localised by active-vision EKF-SLAM or by dead reckoning. The filter
 * predicts from the base's wheel encoders (thesis 4.2.6). The head measures features it acquires
 * and finds again in its stereo pairs through the vision area (`images`, useImages()), or, in
 * tests, a simulated landmark sensor (useSensor()). The plan's known features (5.6.2) start in
 * the map. Legs are repeated from the new estimate until it is within waypoint_tolerance_m;
 * straight legs that would cross one of the plan's tables go round it. The bumper stops it. */
#include <mrolr/hw/Devices.h>
#include <mrolr/hw/SimulatedSensors.h>
#include <mrolr/mission/MissionOptions.h>
#include <mrolr/mission/SelfModel.h>
#include <mrolr/mission/Timeline.h>
#include <mrolr/slam/ActiveSlamFilter.h>
#include <mrolr/vision/VisualSlam.h>

#include <deque>
#include <functional>
#include <memory>
#include <random>
#include <stdexcept>

namespace mrolr::mission
{
/** One sample of the path after a motion step: poses (z, x, φ) in W. */
struct PathSample
{
	double time_s = 0;         ///< the mission's clock
	double device_time_s = 0;  ///< the base's own clock (hw::Odometry::time_s)
	Eigen::Vector3d estimate = Eigen::Vector3d::Zero(), odometry = Eigen::Vector3d::Zero();
	Eigen::Matrix3d P_vv = Eigen::Matrix3d::Zero();
	int features = 0;
	long ticks_right = 0, ticks_left = 0;
	bool bumper = false;
	double compute_s = 0;  ///< robot compute since the previous sample (wall s, not rendering)
};

/** A mapped landmark at the end: label, position in W (m) and covariance (m²). */
struct MappedLandmark
{
	std::string label;
	Eigen::Vector3d p_FinW;
	Eigen::Matrix3d P;
	bool known = false;
};

/** A mapped feature with what a saved map needs: its patch, viewpoint and record (images only). */
struct SavedFeature
{
	MappedLandmark landmark;
	cv::Mat patch;
	Eigen::Vector3d p_viewinW = Eigen::Vector3d::Zero();  ///< head centre when it was first seen
	int successes = 0, failures = 0;                     ///< measurement attempts (5.7)
};

/** One measurement's consistency: its normalised innovation squared against χ²₃. */
struct NisRecord
{
	double time_s = 0;
	std::string feature;
	double nis = 0;
	bool accepted = false;
};

/** The base pressed its bumper: the navigation stops where it is. */
class BumperPressed : public std::runtime_error
{
 public:
	BumperPressed(const std::string& what, const Eigen::Vector3d& estimate)
	    : std::runtime_error(what), estimate_zxphi(estimate)
	{
	}
	Eigen::Vector3d estimate_zxphi;  ///< the robot's estimate when it was pressed
};

/** A stop was requested (SIGINT or SIGTERM): the navigation ends before the next step. */
class StopRequested : public std::runtime_error
{
 public:
	StopRequested() : std::runtime_error("stop requested (SIGINT or SIGTERM)") {}
};

class Navigator
{
 public:
	Navigator(const MissionOptions& o, hw::BaseDevice& base, Timeline& timeline);
	/** landmark_sensor = images: every step's measurements are made by vision::VisualSlam on the
	 * pairs of @p head (the plan's known features with their patches, then features of its own;
	 * the grabbing time goes to the timeline's render time, the rest to compute). */
	void useImages(vision::StereoHeadDevice& head, const std::function<double()>& grab_seconds);
	/** Features the robot's own arm hides, or on it, are neither measured nor added (useImages()
	 * first; @p self must outlive the navigator). */
	void ignoreSelf(const SelfModel& self);
	/** A simulated landmark sensor (tests): measurements of named landmarks; the plan's known
	 * features are measured by their ids. */
	void useSensor(hw::LandmarkSensor& sensor);
	/** Drives to @p goal (z, x, φ in W), going round tables in the way. Throws BumperPressed. */
	void driveTo(const NamedPose& goal);
	/** The current estimate (SLAM or odometry). */
	Eigen::Vector3d estimate();
	Eigen::Matrix3d estimateCovariance();
	const std::vector<PathSample>& path() const { return path_; }
	std::vector<MappedLandmark> map();
	/** Images only: every mapped feature with its patch and record. */
	std::vector<SavedFeature> savedFeatures();
	/** Images only: a feature named @p label acquired where the head is pointed at @p p_aim_inW
	 * (W, m), as an operator points it (5.6.2); false (and @p why) when it was not locked on. */
	bool acquireNamed(const std::string& label, const Eigen::Vector3d& p_aim_inW, std::string& why);
	const std::vector<NisRecord>& nis() const { return nis_; }
	/** Called after every step with the sample just recorded (progress, rawlog). */
	std::function<void(const PathSample&)> on_step;
	/** Called with each navigation measurement from images (the feature, its search regions, the
	 * match, accepted or refused), for a recording. */
	std::function<void(const vision::CycleRecord&)> on_measurement;
	/** Obstacle mode (thesis 5.8.1.2, ObstacleAvoidance.h): called before every translation step
	 * with the estimate and the leg's goal (z, x, φ in W); returns waypoints (z, x in W) to drive
	 * through first, empty when the way is clear. Unset: no checks. */
	std::function<std::vector<Eigen::Vector2d>(const Eigen::Vector3d& estimate,
	                                           const Eigen::Vector3d& goal)>
	    before_translation;
	/** Checked before every step: true stops the navigation (throws StopRequested). */
	std::function<bool()> stop_requested;
	int max_detours_per_leg = 3;  ///< detours on one leg before the rest is driven unchecked
	int measurements = 0, rejected = 0;
	/** Simulated sensors: measurements lost (lost_feature_probability); features deleted by 5.7. */
	int lost = 0, deleted_features = 0;
	int image_cycles = 0, image_matched = 0;  ///< images: cycles that searched, matches found
	int jointly_rejected = 0;  ///< images: matches left out by the joint compatibility test
	int lost_events = 0, recoveries = 0;  ///< images: times it knew it was lost, found the map

 private:
	void addPlanFeatures();
	/** The leg from @p e to @p goal whose swept footprint keeps clear of the plan's tables: the
	 * planned one, else along the heading to the goal's projection; only when @p may_back_off,
	 * else back to the goal's approach point lined up with its heading, else straight back until
	 * turning is clear (@p away names such a move away from the goal); the planned one when
	 * nothing is clear. */
	std::vector<base::PlannedStep> clearPlan(const Eigen::Vector3d& e, const Eigen::Vector3d& goal,
	                                         double reverse_m, bool may_back_off,
	                                         std::string& away);
	/** A point @p goal's heading leads straight into from where turning is clear, if any. */
	std::optional<Eigen::Vector2d> approachPoint(const Eigen::Vector3d& goal);
	/** True when turning in place at @p xv keeps tableMargin() (and @p slack_m) from the tables. */
	bool canTurn(const Eigen::Vector3d& xv, double slack_m = 0);
	/** Clearance kept from the plan's tables: kTurnMargin_m and twice the position's σ. */
	double tableMargin();
	/** Drives through @p via (z, x in W), arriving at each in the direction of travel. */
	void driveThrough(const std::vector<Eigen::Vector2d>& via, Eigen::Vector2d from,
	                  int correction_legs);
	/** Rotate–translate–rotate to @p goal, repeated up to @p correction_legs times; backwards
	 * to a goal close behind only when @p may_reverse (not on a straight approach to a table). */
	void driveStraightTo(const Eigen::Vector3d& goal, int correction_legs, bool may_reverse = true);
	/** Executes @p plan; false when a detour was driven instead of the rest of it, or when the
	 * estimate went off course. With @p towards_goal false (a back-off from a table) the plan's
	 * translations are neither steered towards @p goal nor looked along. */
	bool executeLeg(const std::vector<base::PlannedStep>& plan, const Eigen::Vector3d& goal,
	                int& detours, bool towards_goal = true);
	void execute(const base::PlannedStep& step);
	/** The wheel control the encoders measured over the last step (thesis 4.2.6). */
	base::WheelControl encoderControl(const hw::Odometry& before, const hw::Odometry& after) const;
	void measureWithSensor();
	/** True (and the failed attempt recorded) when feature @p i is lost this time. */
	bool lostThisTime(size_t i);
	/** Deletes the features failing the 5.7 rule (known features are kept). */
	void deleteFailingFeatures();
	/** measurements_per_step cycles of the vision area (the first one predicts with @p u). */
	void measureInImages(const base::WheelControl& u);
	std::vector<size_t> visibleMapped(const std::vector<hw::LandmarkSensor::Sighting>& seen);
	void initialiseNewFeature(const std::vector<hw::LandmarkSensor::Sighting>& seen);
	void noteNis(const std::string& label, double nis, bool accepted);
	/** Images: why the robot is lost (empty when it is not): its estimate's uncertainty grew
	 * beyond steering, or most of its recent searches failed. */
	std::string lostReason();
	void noteAttempt(bool accepted);
	/** Images, after each step: when lost, doubt the estimate and seek the known features. */
	void checkLost();
	void record(const hw::Odometry& odo);

	const MissionOptions& o_;
	hw::BaseDevice& base_;
	Timeline& timeline_;
	base::LabmateModel model_;
	slam::ActiveSlamFilter filter_;
	std::mt19937 rng_;
	std::vector<PathSample> path_;
	std::vector<NisRecord> nis_;
	hw::Odometry last_odometry_;
	double last_compute_s_ = 0;  ///< the timeline's compute at the previous sample
	int detour_depth_ = 0;                       ///< detours being driven inside detours
	std::unique_ptr<vision::VisualSlam> vslam_;  ///< images: the vision area's cycle
	vision::StereoHeadDevice* images_head_ = nullptr;
	std::function<double()> grab_seconds_;
	hw::LandmarkSensor* sensor_ = nullptr;
	std::deque<bool> recent_;  ///< images: the last searches, accepted or not
	int steps_since_relocalise_ = 0;
	int failed_relocalisations_ = 0;  ///< in a row: the doubt grows with them
	int steer_replans_ = 0;           ///< of the leg being driven
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
 * @p tables it would cross, keeping @p clearance_m from the table's edges; empty when the path is
 * clear. */
std::vector<Eigen::Vector2d> detourAroundTables(const std::vector<PlanTable>& tables,
                                                const Eigen::Vector2d& from,
                                                const Eigen::Vector2d& to, double clearance_m);

/** Distance (m) from @p p_zx (z, x in W) to the nearest table footprint of @p tables (0 inside;
 * infinity without tables). */
double distanceToTables(const std::vector<PlanTable>& tables, const Eigen::Vector2d& p_zx);

/** True when the base turning in place at @p p_zx sweeps a disc of @p turn_radius_m that keeps
 * kTurnMargin_m from every table. */
bool canTurnAt(const std::vector<PlanTable>& tables, const Eigen::Vector2d& p_zx,
               double turn_radius_m);
/** Kept between a table and the disc the base sweeps when it turns in place (m), besides twice
 * the position's standard deviation up to kMaxUncertaintyMargin_m. */
constexpr double kTurnMargin_m = 0.05;
constexpr double kMaxUncertaintyMargin_m = 0.1;

}  // namespace mrolr::mission
