// Waypoint navigation with EKF-SLAM or dead reckoning (thesis 5.6.3, 5.7, 7.2.1).
#include <mrolr/mission/Navigator.h>
#include <mrolr/slam/FeatureSelection.h>
#include <mrolr/slam/FeatureVisibility.h>
#include <mrolr/slam/HeadMeasurement.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace mrolr::mission
{
namespace
{
const world::Patch* patchOf(const world::World& w, const std::string& name)
{
	for (const auto& p : w.patches)
		if (p.name == name) return &p;
	return nullptr;
}
}  // namespace

Navigator::Navigator(const MissionOptions& o, hw::BaseDevice& base,
                     std::function<Eigen::Vector3d()> truth, Timeline& timeline)
    : o_(o),
      base_(base),
      truth_(std::move(truth)),
      timeline_(timeline),
      model_(o.labmate),
      filter_(o.slam, model_),
      rng_(o.seed + 101)
{
	filter_.reset(base_.odometry().xv_zxphi);
	// With images every feature needs a saved patch (VisualSlam): no world landmarks then.
	if (o_.navigation.measurement_source != "images")
		for (const auto& l : o_.world.landmarks)
			if (l.known) filter_.addKnownFeature(l.name, l.p_LinW);
	record();
}

Eigen::Vector3d Navigator::estimate()
{
	return o_.mode == NavigationMode::Slam ? filter_.vehicle() : base_.odometry().xv_zxphi;
}

void Navigator::driveTo(const NamedPose& goal)
{
	const Eigen::Vector3d now = estimate();
	const auto via =
	    detourAroundTables(o_.world, {now.x(), now.y()}, {goal.xv_zxphi.x(), goal.xv_zxphi.y()},
	                       o_.navigation.table_clearance_m);
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

void Navigator::execute(const base::PlannedStep& step)
{
	base_.step(step.u);
	timeline_.advance(step.u.dt_s);
	if (o_.mode == NavigationMode::Slam && vslam_)
		measureInImages(step.u);
	else if (o_.mode == NavigationMode::Slam)
	{
		{
			ComputeTimer t(timeline_);
			filter_.predict(step.u);
		}
		measure();
	}
	record();
}

bool Navigator::canSee(const Eigen::Vector3d& xv, const world::Landmark& l) const
{
	const auto c0 = slam::headCentreInW(xv, o_.slam.head.constants);
	if ((l.p_LinW - c0).norm() > o_.navigation.max_range_m) return false;
	if (const auto* p = patchOf(o_.world, l.name); p && p->normal.dot(c0 - p->centre_m) <= 0)
		return false;  // a patch is seen only from its front
	return slam::headCanFixate(xv, l.p_LinW, o_.slam.head) == slam::Visibility::Visible;
}

Eigen::Vector3d Navigator::noisyMeasurement(const Eigen::Vector3d& xv, const Eigen::Vector3d& p)
{
	std::normal_distribution<double> n(0, 1);
	const auto& nav = o_.navigation;
	return slam::predictMeasurement(xv, p, o_.slam.head.constants) +
	       Eigen::Vector3d(nav.true_std_pan_rad * n(rng_), nav.true_std_elevation_rad * n(rng_),
	                       nav.true_std_vergence_rad * n(rng_));
}

std::vector<size_t> Navigator::visibleMapped(const Eigen::Vector3d& xv_true)
{
	std::vector<size_t> out;
	for (size_t i = 0; i < filter_.numFeatures(); ++i)
	{
		const auto* l = o_.world.findLandmark(filter_.info(i).label);
		const bool predicted = slam::assessVisibility(filter_.vehicle(), filter_.feature(i),
		                                              filter_.info(i).p_C0atInitInW,
		                                              o_.slam) == slam::Visibility::Visible;
		if (l && predicted && canSee(xv_true, *l)) out.push_back(i);
	}
	return out;
}

void Navigator::initialiseNewFeature(const Eigen::Vector3d& xv_true)
{
	const world::Landmark* best = nullptr;
	double best_pan = 1e9;
	for (const auto& l : o_.world.landmarks)
	{
		bool mapped = false;
		for (size_t i = 0; i < filter_.numFeatures() && !mapped; ++i)
			mapped = filter_.info(i).label == l.name;
		if (mapped || !canSee(xv_true, l)) continue;
		const double pan =
		    std::abs(slam::predictMeasurement(xv_true, l.p_LinW, o_.slam.head.constants)(0));
		if (pan < best_pan) best = &l, best_pan = pan;
	}
	if (!best) return;
	const auto h = noisyMeasurement(xv_true, best->p_LinW);
	ComputeTimer t(timeline_);
	filter_.initialiseFeature(best->name, h);
}

void Navigator::measure()
{
	const Eigen::Vector3d xv_true = truth_();
	auto visible = visibleMapped(xv_true);
	if (static_cast<int>(visible.size()) < o_.navigation.min_mapped_visible)
		initialiseNewFeature(xv_true);
	std::vector<slam::Observation> obs;
	for (int k = 0; k < o_.navigation.measurements_per_step && !visible.empty(); ++k)
	{
		std::optional<size_t> pick;
		{
			ComputeTimer t(timeline_);
			pick =
			    slam::largestVolume(filter_.stateVector(), filter_.covariance(), visible, o_.slam);
		}
		if (!pick) break;
		const size_t i = visible[*pick];
		visible.erase(visible.begin() + static_cast<long>(*pick));
		timeline_.advance(o_.navigation.measurement_time_s);
		if (lostThisTime(i)) continue;
		obs.push_back(
		    {i, noisyMeasurement(xv_true, o_.world.findLandmark(filter_.info(i).label)->p_LinW)});
	}
	ComputeTimer t(timeline_);
	if (!obs.empty())
	{
		const auto report = filter_.update(obs);
		measurements += static_cast<int>(report.accepted.size());
		rejected += static_cast<int>(report.rejected.size());
		for (size_t i : report.accepted) filter_.recordAttempt(i, true);
		for (size_t i : report.rejected) filter_.recordAttempt(i, false);
	}
	deleteFailingFeatures();
}

bool Navigator::lostThisTime(size_t i)
{
	const double p = o_.navigation.lost_feature_probability;
	if (p <= 0 || std::uniform_real_distribution<double>(0, 1)(rng_) >= p) return false;
	filter_.recordAttempt(i, false);
	++lost;
	return true;
}

void Navigator::deleteFailingFeatures()
{
	for (size_t i = filter_.numFeatures(); i-- > 0;)
		if (!filter_.info(i).known && filter_.shouldDelete(i))
		{
			filter_.deleteFeature(i);
			++deleted_features;
		}
}

void Navigator::record()
{
	PathSample s;
	s.time_s = timeline_.simulatedSeconds();
	s.truth = truth_();
	const auto odo = base_.odometry();
	s.odometry = odo.xv_zxphi;
	s.ticks_right = odo.ticks_right, s.ticks_left = odo.ticks_left;
	s.estimate = estimate();
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
		out.push_back({filter_.info(i).label, filter_.feature(i), filter_.featureCovariance(i)});
	return out;
}

}  // namespace mrolr::mission
