// Waypoint navigation with EKF-SLAM or dead reckoning (thesis 5.6.3, 5.7, 7.2.1).
#include <mrolr/mission/Navigator.h>
#include <mrolr/slam/FeatureSelection.h>
#include <mrolr/slam/FeatureVisibility.h>

#include <algorithm>
#include <cmath>
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

void Navigator::useSensor(hw::LandmarkSensor& sensor)
{
	sensor_ = &sensor;
	addPlanFeatures();
}

void Navigator::addPlanFeatures()
{
	for (const auto& k : o_.plan.known_features)
		if (vslam_)
			vslam_->addKnownFeature(k.id, k.p_FinW, covarianceOf(k), k.patch);
		else
			filter_.addKnownFeature(k.id, k.p_FinW, covarianceOf(k));
}

Eigen::Vector3d Navigator::estimate()
{
	return o_.mode == NavigationMode::Slam ? filter_.vehicle() : base_.odometry().xv_zxphi;
}

Eigen::Matrix3d Navigator::estimateCovariance()
{
	return o_.mode == NavigationMode::Slam ? filter_.vehicleCovariance() : Eigen::Matrix3d::Zero();
}

void Navigator::driveTo(const NamedPose& goal)
{
	const Eigen::Vector3d now = estimate();
	const auto via =
	    detourAroundTables(o_.plan.tables, {now.x(), now.y()},
	                       {goal.xv_zxphi.x(), goal.xv_zxphi.y()}, o_.navigation.table_clearance_m);
	driveThrough(via, {now.x(), now.y()}, o_.navigation.max_correction_legs);
	driveStraightTo(goal.xv_zxphi, o_.navigation.max_correction_legs);
	timeline_.note("reached " + goal.name);
}

void Navigator::driveThrough(const std::vector<Eigen::Vector2d>& via, Eigen::Vector2d from,
                             int correction_legs)
{
	for (const auto& v : via)
	{
		const double heading = std::atan2(v.y() - from.y(), v.x() - from.x());
		driveStraightTo({v.x(), v.y(), heading}, correction_legs);
		from = v;
	}
}

void Navigator::driveStraightTo(const Eigen::Vector3d& goal, int correction_legs)
{
	int detours = 0;
	for (int leg = 0; leg <= correction_legs; ++leg)
	{
		const Eigen::Vector3d e = estimate();
		const bool close =
		    (e.head<2>() - goal.head<2>()).norm() < o_.navigation.waypoint_tolerance_m;
		if (leg > 0 && close && std::abs(base::wrapAngle(e.z() - goal.z())) < 0.02) return;
		std::vector<base::PlannedStep> plan;
		{
			ComputeTimer t(timeline_);
			// Obstacle mode looks ahead before each translation: no reversing blind.
			const double reverse_m = before_translation ? 0.0 : o_.navigation.reverse_max_m;
			plan = planMissionLeg(e, goal, model_, o_.trajectory, reverse_m);
		}
		if (!executeLeg(plan, goal, detours)) leg = -1;  // round an obstacle: plan the leg anew
	}
}

bool Navigator::executeLeg(const std::vector<base::PlannedStep>& plan, const Eigen::Vector3d& goal,
                           int& detours)
{
	for (const auto& s : plan)
	{
		const bool check = before_translation && s.kind == base::PlannedStep::Kind::Translate &&
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
	base_.step(step.u);
	timeline_.advance(step.u.dt_s);
	const hw::Odometry odo = base_.odometry();
	const base::WheelControl u = encoderControl(last_odometry_, odo);
	last_odometry_ = odo;
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
