// Waypoint navigation with EKF-SLAM or dead reckoning (thesis 5.6.3, 5.7, 7.2.1).
#include <mrolr/mission/FootprintSweep.h>
#include <mrolr/mission/Navigator.h>
#include <mrolr/slam/FeatureSelection.h>
#include <mrolr/slam/FeatureVisibility.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <sstream>

namespace mrolr::mission
{
namespace
{
Eigen::Matrix3d covarianceOf(const PlanFeature& k)
{
	return k.sigma_m.cwiseAbs2().asDiagonal();
}

std::string where(const Eigen::Vector3d& e)
{
	std::ostringstream s;
	s.precision(2);
	s << std::fixed << "(z " << e.x() << ", x " << e.y() << ") m";
	return s.str();
}
}  // namespace

namespace
{
/** @p goal moved onto the line of @p e's heading (its projection), with the goal's heading. */
Eigen::Vector3d alongHeading(const Eigen::Vector3d& e, const Eigen::Vector3d& goal)
{
	const Eigen::Vector2d dir(std::cos(e.z()), std::sin(e.z()));
	const Eigen::Vector2d p = e.head<2>() + dir * dir.dot(goal.head<2>() - e.head<2>());
	return {p.x(), p.y(), goal.z()};
}
}  // namespace

Navigator::Navigator(const MissionOptions& o, hw::BaseDevice& base, Timeline& timeline)
    : o_(o),
      base_(base),
      timeline_(timeline),
      model_(o.labmate),
      filter_(o.slam, model_),
      rng_(o.seed + 101)
{
	last_odometry_ = base_.odometry();
	filter_.reset(o.plan.start().xv_zxphi);
	record(last_odometry_);
}

void Navigator::useImages(vision::StereoHeadDevice& head,
                          const std::function<double()>& grab_seconds)
{
	vslam_ = std::make_unique<vision::VisualSlam>(filter_, geometry::BiSightHead(o_.bisight),
	                                              o_.vision, model_);
	images_head_ = &head;
	grab_seconds_ = grab_seconds;
	addPlanFeatures();
}

void Navigator::ignoreSelf(const SelfModel& self)
{
	if (vslam_)
		vslam_->self_occludes = [&self](const Eigen::Vector3d& p_inC0_m) { return self.isSelf(p_inC0_m); };
}

void Navigator::useSensor(hw::LandmarkSensor& sensor)
{
	sensor_ = &sensor;
	addPlanFeatures();
}

void Navigator::addPlanFeatures()
{
	for (const auto& k : o_.plan.known_features)
		if (vslam_)
			vslam_->addKnownFeature(k.id, k.p_FinW, covarianceOf(k), k.patch, k.p_viewinW);
		else
			filter_.addKnownFeature(k.id, k.p_FinW, covarianceOf(k), k.p_viewinW);
}

Eigen::Vector3d Navigator::estimate()
{
	return o_.mode == NavigationMode::Slam ? filter_.vehicle() : base_.odometry().xv_zxphi;
}

Eigen::Matrix3d Navigator::estimateCovariance()
{
	return o_.mode == NavigationMode::Slam ? filter_.vehicleCovariance() : Eigen::Matrix3d::Zero();
}

double Navigator::tableMargin()
{
	// The tables are where the plan says, the base where it believes: keep twice its position's
	// standard deviation besides the fixed margin.
	const double sigma = std::sqrt(estimateCovariance().topLeftCorner<2, 2>().eigenvalues().real().maxCoeff());
	return kTurnMargin_m + std::min(2 * sigma, kMaxUncertaintyMargin_m);
}

bool Navigator::canTurn(const Eigen::Vector3d& xv, double slack_m)
{
	return distanceToTables(o_.plan.tables, xv.head<2>()) >=
	       o_.labmate.turnRadius() + tableMargin() + slack_m;
}

namespace
{
/** Distances tried, shortest first, for moving straight to where the base can turn (m). */
constexpr double kStraightSteps_m[] = {0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.8, 1.0, 1.25, 1.5};
/** The longest move backwards, where the head does not look (m): about the base's length. */
constexpr double kMaxBlindBack_m = 0.6;
/** The approach point of a goal next to a table keeps this much more clearance than a turn
 * needs, so that arriving a little off it still leaves room to turn (m). */
constexpr double kApproachSlack_m = 0.15;
/** Back-offs from a table on one leg before the rest is driven as planned. */
constexpr int kMaxBackOffs = 3;
/** Next to a table the base moves straight to a goal's projection only when its heading is this
 * close to the goal's (rad); otherwise it first moves to where it can turn. */
constexpr double kStraightAlign_rad = 5.0 * M_PI / 180.0;
/** Replans of one leg for being off course before the rest is driven as planned. */
constexpr int kMaxSteerReplans = 12;

Eigen::Vector2d along(const Eigen::Vector3d& xv, double d)
{
	return xv.head<2>() + d * Eigen::Vector2d(std::cos(xv.z()), std::sin(xv.z()));
}
}  // namespace

std::optional<Eigen::Vector2d> Navigator::approachPoint(const Eigen::Vector3d& goal)
{
	if (canTurn(goal)) return std::nullopt;
	for (double d : kStraightSteps_m)
		if (const Eigen::Vector2d a = along(goal, -d); canTurn({a.x(), a.y(), goal.z()}, kApproachSlack_m))
			return a;
	return std::nullopt;
}

void Navigator::driveTo(const NamedPose& goal)
{
	const Eigen::Vector3d now = estimate();
	const auto approach = approachPoint(goal.xv_zxphi);
	const Eigen::Vector2d last = approach ? *approach : goal.xv_zxphi.head<2>();
	auto via = detourAroundTables(o_.plan.tables, now.head<2>(), last,
	                              o_.navigation.table_clearance_m);
	if (approach)  // then straight in: no turning next to the table
	{
		via.push_back(*approach);
		timeline_.note("approaching " + goal.name + " straight from " +
		               where({approach->x(), approach->y(), 0}));
	}
	driveThrough(via, now.head<2>(), o_.navigation.max_correction_legs);
	driveStraightTo(goal.xv_zxphi, o_.navigation.max_correction_legs, !approach);
	timeline_.note("reached " + goal.name);
}

void Navigator::driveThrough(const std::vector<Eigen::Vector2d>& via, Eigen::Vector2d from,
                             int correction_legs)
{
	for (const auto& v : via)
	{
		const double heading = std::atan2(v.y() - from.y(), v.x() - from.x());
		// A via point (round an obstacle) where the base could not turn next to a plan's table is
		// drawn back along the way to it until it can; one with no such point is left out.
		std::optional<Eigen::Vector2d> reachable;
		if (canTurn({v.x(), v.y(), heading}))
			reachable = v;
		else
			for (double d : kStraightSteps_m)
				if (const Eigen::Vector2d a = along({v.x(), v.y(), heading}, -d);
				    (a - from).dot(v - from) > 0 && canTurn({a.x(), a.y(), heading}))
				{
					reachable = a;
					break;
				}
		if (!reachable) continue;
		driveStraightTo({reachable->x(), reachable->y(), heading}, correction_legs);
		from = *reachable;
	}
}

std::vector<base::PlannedStep> Navigator::clearPlan(const Eigen::Vector3d& e,
                                                    const Eigen::Vector3d& goal, double reverse_m,
                                                    bool may_back_off, std::string& away)
{
	away.clear();
	const double margin = tableMargin();
	auto blocked = [&](const std::vector<base::PlannedStep>& p)
	{ return firstBlockedStep(o_.plan.tables, o_.labmate, e, p, margin).has_value(); };
	auto plan = planMissionLeg(e, goal, model_, o_.trajectory, reverse_m);
	if (!blocked(plan)) return plan;
	// Next to a table, already facing the goal's heading: along it to the goal's projection ...
	if (std::abs(base::wrapAngle(goal.z() - e.z())) < kStraightAlign_rad)
	{
		auto straight = planMissionLeg(e, alongHeading(e, goal), model_, o_.trajectory, 1.0);
		if (!blocked(straight)) return straight;
	}
	if (!may_back_off) return plan;
	// ... or back to where the goal's heading leads straight in from, lined up with it: driving
	// in askew sweeps the footprint's corner further ahead than its front ...
	if (const auto a = approachPoint(goal))
	{
		auto line_up = planMissionLeg(e, {a->x(), a->y(), goal.z()}, model_, o_.trajectory, 1.6);
		if (!blocked(line_up))
		{
			away = "lining up with the goal's heading away from the table";
			return line_up;
		}
	}
	// ... or straight back (or on) until turning there is clear; backwards the head does not see,
	// so never further than kMaxBlindBack_m, and not again once backing off did not help.
	for (double d : kStraightSteps_m)
		for (double sign : {-1.0, 1.0})
			if (const Eigen::Vector2d b = along(e, sign * d);
			    (sign > 0 || d <= kMaxBlindBack_m) && canTurn({b.x(), b.y(), e.z()}))
			{
				auto move = planMissionLeg(e, {b.x(), b.y(), e.z()}, model_, o_.trajectory, 1.6);
				if (blocked(move)) continue;
				away = "backing away from the table to turn";
				return move;
			}
	return plan;  // nothing clear from here: the bumper will say so
}

void Navigator::driveStraightTo(const Eigen::Vector3d& goal, int correction_legs,
                                bool may_reverse)
{
	int detours = 0, backs = 0;
	steer_replans_ = 0;
	for (int leg = 0; leg <= correction_legs; ++leg)
	{
		const Eigen::Vector3d e = estimate();
		const bool close =
		    (e.head<2>() - goal.head<2>()).norm() < o_.navigation.waypoint_tolerance_m;
		if (leg > 0 && close && std::abs(base::wrapAngle(e.z() - goal.z())) < 0.02) return;
		std::vector<base::PlannedStep> plan;
		std::string away;
		{
			ComputeTimer t(timeline_);
			// Obstacle mode looks ahead before each translation: no reversing blind.
			const double reverse_m =
			    before_translation || !may_reverse ? 0.0 : o_.navigation.reverse_max_m;
			plan = clearPlan(e, goal, reverse_m, backs < kMaxBackOffs, away);
		}
		const bool backing = !away.empty();
		if (backing)
		{
			++backs;
			timeline_.note(away);
			--leg;  // moving away to come in again is not a correction of its own
		}
		// round an obstacle or off course: plan the leg anew (a back-off is a move of its own, not
		// a step towards the goal, so it is neither steered nor looked along)
		if (!executeLeg(plan, goal, detours, !backing)) leg = -1;
	}
}

namespace
{
/** A translation is replanned when the estimate's heading is off the bearing to the leg's goal
 * by more than this (rad): legs are driven closed-loop, not blind rotate–translate–rotate. */
constexpr double kSteerTolerance_rad = 3.0 * M_PI / 180.0;
/** ... unless the goal is this close (m): a last short step is not worth a turn. */
constexpr double kSteerMinDistance_m = 0.1;

/** True when the next translation of @p amount_m should be replanned from the estimate @p e. */
bool offCourse(const Eigen::Vector3d& e, const Eigen::Vector3d& goal, double amount_m)
{
	const Eigen::Vector2d d = goal.head<2>() - e.head<2>();
	if (d.norm() < kSteerMinDistance_m) return false;
	const double bearing = std::atan2(d.y(), d.x()) + (amount_m < 0 ? M_PI : 0.0);
	return std::abs(base::wrapAngle(bearing - e.z())) > kSteerTolerance_rad;
}
}  // namespace

bool Navigator::executeLeg(const std::vector<base::PlannedStep>& plan, const Eigen::Vector3d& goal,
                           int& detours, bool towards_goal)
{
	for (const auto& s : plan)
	{
		const bool translation = s.kind == base::PlannedStep::Kind::Translate;
		// the look is along the heading: only a forward step towards the goal is looked along
		const bool check = before_translation && translation && towards_goal && s.amount > 0 &&
		                   detours < max_detours_per_leg && detour_depth_ < 2;
		if (check)
			if (const auto via = before_translation(estimate(), goal); !via.empty())
			{
				++detours, ++detour_depth_;
				const Eigen::Vector3d e = estimate();
				driveThrough(via, e.head<2>(), o_.navigation.max_correction_legs);
				--detour_depth_;
				return false;
			}
		// closed loop: off course before a translation (a slipped turn, a drift) replans the leg
		if (translation && towards_goal && steer_replans_ < kMaxSteerReplans &&
		    offCourse(estimate(), goal, s.amount))
		{
			++steer_replans_;
			return false;
		}
		execute(s);
	}
	return true;
}

base::WheelControl Navigator::encoderControl(const hw::Odometry& before,
                                             const hw::Odometry& after) const
{
	const double dt = after.time_s - before.time_s;
	if (!(dt > 0)) return {0, 0, 0};
	const double per_m = o_.labmate.encoder_ticks_per_m;
	return {double(after.ticks_right - before.ticks_right) / per_m / dt,
	        double(after.ticks_left - before.ticks_left) / per_m / dt, dt};
}

void Navigator::execute(const base::PlannedStep& step)
{
	if (stop_requested && stop_requested()) throw StopRequested();
	if (vslam_ && step.kind == base::PlannedStep::Kind::Rotate)
	{  // measurements through a turn: the head keeps its feature in view while the base turns
		ComputeTimer t(timeline_);
		const Eigen::Vector3d e = filter_.vehicle();
		vslam_->holdGaze({e.x(), e.y(), e.z() + step.amount}, *images_head_);
	}
	base_.step(step.u);
	timeline_.advance(step.u.dt_s);
	const hw::Odometry odo = base_.odometry();
	const base::WheelControl u = encoderControl(last_odometry_, odo);
	last_odometry_ = odo;
	try
	{
		if (o_.mode == NavigationMode::Slam && vslam_)
			measureInImages(u);
		else if (o_.mode == NavigationMode::Slam)
		{
			{
				ComputeTimer t(timeline_);
				filter_.predict(u);
			}
			if (sensor_) measureWithSensor();
		}
	}
	catch (...)
	{
		record(odo);  // the step was driven: it stays in the record when a device fails after it
		throw;
	}
	record(odo);
	if (odo.bumper)
		throw BumperPressed("collision: the bumper was pressed at the estimated " +
		                        where(estimate()),
		                    estimate());
}

void Navigator::noteNis(const std::string& label, double nis, bool accepted)
{
	nis_.push_back({timeline_.simulatedSeconds(), label, nis, accepted});
}

void Navigator::record(const hw::Odometry& odo)
{
	PathSample s;
	s.time_s = timeline_.simulatedSeconds();
	s.device_time_s = odo.time_s;
	s.odometry = odo.xv_zxphi;
	s.ticks_right = odo.ticks_right, s.ticks_left = odo.ticks_left;
	s.bumper = odo.bumper;
	s.estimate = estimate();
	s.compute_s = timeline_.computeSeconds() - last_compute_s_;
	last_compute_s_ = timeline_.computeSeconds();
	if (o_.mode == NavigationMode::Slam)
	{
		s.P_vv = filter_.vehicleCovariance();
		s.features = static_cast<int>(filter_.numFeatures());
	}
	path_.push_back(s);
	if (on_step) on_step(s);
}

std::vector<MappedLandmark> Navigator::map()
{
	std::vector<MappedLandmark> out;
	if (o_.mode != NavigationMode::Slam) return out;
	for (size_t i = 0; i < filter_.numFeatures(); ++i)
		out.push_back({filter_.info(i).label, filter_.feature(i), filter_.featureCovariance(i),
		               filter_.info(i).known});
	return out;
}

}  // namespace mrolr::mission
