// The mission's state machine (thesis fig 5.8.1.5) on the robot's devices.
#include <mrolr/geometry/Frames.h>
#include <mrolr/geometry/GeometryError.h>
#include <mrolr/hw_serial/SerialError.h>
#include <mrolr/mission/Mission.h>
#include <mrolr/mission/MissionStereoHead.h>
#include <mrolr/model/SceneModel.h>
#include <mrolr/model/WireFrameIO.h>
#include <mrolr/stereo/HeadCalibration.h>
#include <mrolr/util/Config.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>

namespace mrolr::mission
{
namespace
{
RobotDevices checked(RobotDevices d)
{
	if (!d.base || !d.head || !d.arm)
		throw std::invalid_argument("Mission: every device (base, head, arm) must be given");
	return d;
}

void requireSensors(const MissionOptions& o, const SimulatedSensors& s)
{
	if (o.navigation.landmark_source == LandmarkSource::Simulated && !s.landmarks)
		throw util::ConfigError("[navigation] landmark_sensor = " + o.navigation.landmark_sensor +
		                        ": a simulated sensor, but no simulator provides it");
	if (o.search.scene_source == SceneSource::Simulated && !s.scenes)
		throw util::ConfigError("[search] scene_sensor = " + o.search.scene_sensor +
		                        ": a simulated sensor, but no simulator provides it");
}
}  // namespace

struct Mission::Impl
{
	const MissionOptions& o;
	MissionResult r;
	RobotDevices dev;
	SimulatedSensors sensors;
	model::WireFrame target;
	std::unique_ptr<Navigator> nav;
	std::unique_ptr<ObjectSearch> search;
	std::unique_ptr<ObstacleAvoidance> obstacles;  ///< obstacle mode
	std::unique_ptr<MissionStereoHead> nav_head;   ///< landmark_sensor = images
	std::function<void(const std::string&, const PathSample&)>* progress = nullptr;
	std::atomic<bool>* stop_flag = nullptr;
	bool render_failed = false;

	Impl(const MissionOptions& opts, RobotDevices d, SimulatedSensors s)
	    : o(opts), dev(checked(std::move(d))), sensors(s)
	{
		requireSensors(o, sensors);
	}
	hw::StereoImages grabStereo(StereoShot::Purpose purpose = StereoShot::Purpose::Table);
	SearchView reconstructedView(const geometry::HeadAngles& angles);
	SearchView simulatedView(const geometry::HeadAngles& angles);
	void attachObstacleMode();
	void stopSafely(const std::string& why);
	void runStages();
	void loadTarget();
	void navigate();
	bool searchStation(const NamedPose& station);
	void retrieve();
	void goHome();
	void finish();
	Eigen::Isometry3d predictedInC0(const Eigen::Isometry3d& T_OinW_m,
	                                const Eigen::Vector3d& xv) const;
	std::optional<Eigen::Isometry3d> dockAndReobserve(const Retrieval& retrieval,
	                                                  const PlanTable& table,
	                                                  const Eigen::Isometry3d& T_OinW_m,
	                                                  double top_height_m);
	std::optional<Eigen::Isometry3d> reobserveAt(const Eigen::Isometry3d& T_OinC0_mm);
};

void Mission::Impl::loadTarget()
{
	r.timeline.beginStage("load_target");
	ComputeTimer t(r.timeline);
	const auto file = (std::filesystem::path(o.models_dir) / (o.target + ".wf")).string();
	target = model::loadWireFrame(file);
	ViewSource views = [this](const geometry::HeadAngles& a) { return reconstructedView(a); };
	if (o.search.scene_source == SceneSource::Simulated)
		views = [this](const geometry::HeadAngles& a) { return simulatedView(a); };
	search = std::make_unique<ObjectSearch>(o, target, views);
	r.timeline.note("target model " + o.target + " (" + file + "): " +
	                std::to_string(target.lines.size()) + " lines, " +
	                std::to_string(target.conics.size()) + " conics");
}

hw::StereoImages Mission::Impl::grabStereo(StereoShot::Purpose purpose)
{
	const auto t0 = std::chrono::steady_clock::now();
	auto images = dev.head->grab();
	StereoShot shot{nav->path().back(), images.angles, images.left, images.right, images.frame,
	                purpose};
	shot.state.time_s = r.timeline.simulatedSeconds();
	r.shots.push_back(std::move(shot));
	r.timeline.addRender(
	    std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
	return images;
}

/** A view reconstructed from a new stereo pair, with the pair's edges for image verification
 * ([search] image_verification). */
SearchView Mission::Impl::reconstructedView(const geometry::HeadAngles& angles)
{
	dev.head->moveTo(angles);
	const auto images = grabStereo();
	ComputeTimer t(r.timeline);
	const auto calib = stereo::calibrationFromHead(geometry::BiSightHead(o.bisight), images.angles);
	const cv::Mat left = images.left.asCvMat<cv::Mat>(mrpt::img::SHALLOW_COPY);
	const cv::Mat right = images.right.asCvMat<cv::Mat>(mrpt::img::SHALLOW_COPY);
	SearchView view{model::sceneToWireFrame(stereo::reconstructScene(left, right, calib, o.scene)),
	                {},
	                images.frame};
	if (o.search.image_verification)
		view.images =
		    std::make_shared<recog::ImageVerifier>(left, right, calib, o.image_verification);
	return view;
}

/** A simulated scene sensor's view (tests); the pair is grabbed for the record when asked. */
SearchView Mission::Impl::simulatedView(const geometry::HeadAngles& angles)
{
	dev.head->moveTo(angles);
	if (o.search.render_stereo && !render_failed) try
		{
			grabStereo();
		}
		catch (const hw::SerialDeviceError&)
		{
			throw;  // the head stopped answering: the mission stops
		}
		catch (const std::exception& e)
		{  // the recording loses its images, the mission goes on (and says so)
			r.timeline.note(std::string("stereo grab failed, no more images: ") + e.what());
			render_failed = true;
		}
	return {sensors.scenes->scene(angles), {}, std::nullopt};
}

void Mission::Impl::attachObstacleMode()
{
	auto look = [this](const geometry::HeadAngles& a)
	{
		dev.head->moveTo(a);
		return grabStereo(StereoShot::Purpose::Obstacle);
	};
	obstacles = std::make_unique<ObstacleAvoidance>(geometry::BiSightHead(o.bisight), o.obstacle,
	                                                look, r.timeline);
	attachObstacleAvoidance(*nav, *obstacles, o);
}

void Mission::Impl::navigate()
{
	r.timeline.beginStage("navigate");
	nav = std::make_unique<Navigator>(o, *dev.base, r.timeline);
	nav->on_step = [this](const PathSample& s)
	{
		if (progress && *progress) (*progress)(r.timeline.stage(), s);
	};
	nav->stop_requested = [this] { return stop_flag && stop_flag->load(); };
	if (o.obstacle_mode) attachObstacleMode();
	r.navigation_source = o.navigation.landmark_sensor;
	if (o.mode == NavigationMode::Slam && o.navigation.landmark_source == LandmarkSource::Images)
	{
		nav_head = std::make_unique<MissionStereoHead>(*dev.head);
		nav->useImages(*nav_head, [this] { return nav_head->grabSeconds(); });
	}
	else if (o.mode == NavigationMode::Slam)
		nav->useSensor(*sensors.landmarks);
	else
		r.navigation_source = "dead_reckoning";
	for (size_t i = 1; i < o.plan.route.size(); ++i) nav->driveTo(o.plan.route[i]);
}

bool Mission::Impl::searchStation(const NamedPose& station)
{
	r.timeline.beginStage("navigate");
	nav->driveTo(station);
	r.timeline.beginStage("search");
	++r.stations_searched;
	r.search = search->sweep(r.timeline, nav->estimate());
	r.search_xv_estimate = nav->estimate();
	r.timeline.note(station.name + ": " + (r.search.found ? "found" : "not found"));
	if (r.search.found) r.found_at_station = station.name;
	return r.search.found;
}

/** The object at @p T_OinW_m seen from C0 of the base at @p xv (mm). */
Eigen::Isometry3d Mission::Impl::predictedInC0(const Eigen::Isometry3d& T_OinW_m,
                                               const Eigen::Vector3d& xv) const
{
	Eigen::Isometry3d T = geometry::T_C0inW(xv, o.bisight.head_height_m).inverse() * T_OinW_m;
	T.translation() *= 1000.0;
	return T;
}

void Mission::Impl::retrieve()
{
	r.timeline.beginStage("retrieve");
	auto reobserve = [&](const Eigen::Isometry3d& T_OinC0_mm) { return reobserveAt(T_OinC0_mm); };
	Eigen::Isometry3d T_OinW = r.search.T_OinC0;
	T_OinW.translation() /= 1000.0;
	T_OinW = geometry::T_C0inW(r.search_xv_estimate, o.bisight.head_height_m) * T_OinW;
	const PlanTable* table = tableUnder(o.plan.tables, T_OinW.translation());
	const double top_height_m = table ? table->top_height_m : 0.0;
	Retrieval retrieval(o, target);
	Eigen::Isometry3d T_OinC0_mm = r.search.T_OinC0;
	std::optional<uint64_t> frame = r.search.frame;
	if (o.docking.drive_to_reach &&
	    !retrieval.feasibleAt(T_OinC0_mm, top_height_m, &r.docking.reasons_before))
	{
		r.docking.needed = true;
		if (!table)
			r.docking.reason = "the plan has no table to dock at";
		else if (const auto T = dockAndReobserve(retrieval, *table, T_OinW, top_height_m))
			T_OinC0_mm = *T, frame = r.docking.frame;
	}
	r.retrieval = retrieval.run(T_OinC0_mm, top_height_m, *dev.arm, reobserve, r.timeline);
	r.retrieval.frame = frame;
	r.retrieved = r.retrieval.retrieved;
	if (!r.retrieval.feasible) r.failure = "grasp not feasible: " + r.retrieval.reasons.front();
	if (!r.retrieval.feasible && r.docking.needed && !r.docking.planned)
		r.failure += " (docking: " + r.docking.reason + ")";
	if (r.retrieved) r.timeline.note("object held (jaws " + std::to_string(r.retrieval.width_lifted_mm) + " mm apart)");
}

/** The first candidate docking pose (DockPlanner.h) from which the grasp is feasible, driven to;
 * the object is recognised again from there. Returns its pose in C0 there (mm): recognised, or
 * predicted from the search and the navigation's estimate when not recognised; nothing when no
 * candidate gives a feasible grasp (the base has not moved). */
std::optional<Eigen::Isometry3d> Mission::Impl::dockAndReobserve(const Retrieval& retrieval,
                                                                 const PlanTable& table,
                                                                 const Eigen::Isometry3d& T_OinW_m,
                                                                 double top_height_m)
{
	auto& d = r.docking;
	const auto t0 = std::chrono::steady_clock::now();
	{
		ComputeTimer timer(r.timeline);
		const auto candidates =
		    dockCandidates(o.plan.tables, table, T_OinW_m.translation(), nav->estimate(),
		                   o.dock.T_C0inA, o.bisight.head_height_m,
		                   o.navigation.table_clearance_m, o.docking);
		d.candidates = static_cast<int>(candidates.size());
		for (const auto& c : candidates)
		{
			++d.candidates_checked;
			std::vector<std::string> why;
			if (!retrieval.feasibleAt(predictedInC0(T_OinW_m, c.pose.xv_zxphi), top_height_m, &why))
			{
				if (d.candidates_checked == 1) d.reasons_nearest = why;
				continue;
			}
			d.planned = true, d.chosen = c;
			break;
		}
	}
	d.compute_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
	if (!d.planned)
	{
		d.reason = "none of " + std::to_string(d.candidates) + " docking poses round table." +
		           table.name + " gives a feasible grasp";
		r.timeline.note("docking: " + d.reason);
		return std::nullopt;
	}
	const auto& xv = d.chosen.pose.xv_zxphi;
	r.timeline.note("docking at " + d.chosen.side + " (z " + std::to_string(xv[0]) + " m, x " +
	                std::to_string(xv[1]) + " m, " + std::to_string(xv[2] * 180 / M_PI) +
	                " deg), " + std::to_string(d.chosen.travel_m) + " m to drive");
	r.timeline.beginStage("dock");
	nav->driveTo(d.chosen.pose);
	r.timeline.beginStage("retrieve");
	const Eigen::Isometry3d predicted = predictedInC0(T_OinW_m, nav->estimate());
	SearchResult s;
	try
	{
		r.timeline.advance(o.search.head_move_time_s);
		s = search->observe(search->fixationAngles(predicted), r.timeline);
	}
	catch (const geometry::GeometryError& e)
	{
		r.timeline.note(std::string("docking: cannot fixate the object: ") + e.what());
	}
	d.frame = s.frame;
	d.recognised = d.reached = s.found;
	d.ambiguous = s.found && s.recognition.ambiguous;
	r.timeline.note(std::string("docking view: ") + (s.found ? "recognised" : "not recognised"));
	if (s.found) return s.T_OinC0;
	d.reason = "not recognised again at the docking pose: grasp planned on the pose predicted "
	           "from the search and the navigation's estimate";
	return predicted;
}

/** The visual verification's view: the head fixates the object's estimated centre and a new
 * stereo pair is recognised as in the sweep. */
std::optional<Eigen::Isometry3d> Mission::Impl::reobserveAt(const Eigen::Isometry3d& T_OinC0_mm)
{
	geometry::HeadAngles angles;
	try
	{
		angles = search->fixationAngles(T_OinC0_mm);
	}
	catch (const geometry::GeometryError& e)
	{
		r.timeline.note(std::string("verification: cannot fixate the object: ") + e.what());
		return std::nullopt;
	}
	r.timeline.advance(o.search.head_move_time_s);
	const auto s = search->observe(angles, r.timeline);
	r.timeline.note(std::string("verification view (object fixated): ") +
	                (s.found ? "recognised" : "not recognised"));
	return s.found ? std::optional(s.T_OinC0) : std::nullopt;
}

void Mission::Impl::goHome()
{
	r.timeline.beginStage("return_home");
	nav->driveTo(o.plan.home);
	r.timeline.endStage();
}

void Mission::Impl::finish()
{
	r.home = o.plan.home;
	if (dev.links) r.links = dev.links();
	if (obstacles) r.obstacle = obstacles->report();
	if (nav)  // no device I/O here: a device may have failed
	{
		r.path = nav->path();
		r.home_estimate_error_m = (r.path.back().estimate.head<2>() - r.home.xv_zxphi.head<2>()).norm();
		r.map = nav->map();
		r.nis = nav->nis();
		r.measurements = nav->measurements;
		r.measurements_rejected = nav->rejected;
		r.measurements_lost = nav->lost;
		r.features_deleted = nav->deleted_features;
		r.image_searches = nav->image_cycles;
		r.image_matches = nav->image_matched;
		r.jointly_rejected = nav->jointly_rejected;
		r.lost_events = nav->lost_events, r.recoveries = nav->recoveries;
	}
	if (nav_head) r.navigation_pairs = nav_head->grabs();
	r.returned_home = nav && !r.stopped && r.home_estimate_error_m <= o.home_tolerance_m;
	r.success = r.found && r.retrieved && r.returned_home && !r.stopped;
	if (r.failure.empty() && !r.found)
		r.failure = "target '" + o.target + "' not found at any of " +
		            std::to_string(r.stations_searched) + " search stations";
	if (r.failure.empty() && !r.returned_home)
		r.failure = "did not return home within tolerance (its own estimate)";
}

void Mission::Impl::runStages()
{
	loadTarget();
	navigate();
	for (const auto& station : o.plan.stations)
		if ((r.found = searchStation(station))) break;
	if (r.found) retrieve();
	goHome();
	if (r.retrieved)
	{
		r.held_width_mm = dev.arm->gripperWidthMm();
		if (r.held_width_mm < o.retrieval.min_held_width_mm)
		{
			r.retrieved = false;
			r.failure = "the object was lost on the way home (jaws " +
			            std::to_string(r.held_width_mm) + " mm apart)";
		}
	}
}

void Mission::Impl::stopSafely(const std::string& why)
{
	r.stopped = true;
	r.failure = "stopped: " + why;
	r.timeline.note(r.failure);
	// Steps are discrete (the base stands still between them); a zero step makes sure of it.
	try
	{
		dev.base->step({0, 0, 0});
		r.timeline.note("base stopped");
	}
	catch (const std::exception& stop_error)
	{
		r.timeline.note(std::string("could not command the base to stop: ") + stop_error.what());
	}
	r.timeline.endStage();
}

Mission::Mission(const MissionOptions& o, RobotDevices devices, SimulatedSensors sensors)
    : impl_(std::make_unique<Impl>(o, std::move(devices), sensors))
{
}
Mission::~Mission() = default;

MissionResult Mission::run()
{
	auto& m = *impl_;
	m.progress = &on_progress;
	m.stop_flag = stop_flag;
	m.r.target = m.o.target;
	try
	{
		m.runStages();
	}
	catch (const StopRequested& e)
	{
		m.r.interrupted = true;
		m.stopSafely(e.what());
	}
	catch (const BumperPressed& e)
	{
		m.r.collided = true;
		m.r.collision_estimate = e.estimate_zxphi;
		m.stopSafely(e.what());
	}
	catch (const hw::SerialDeviceError& e)
	{  // a device stopped answering: stop where we are, keep what was recorded
		m.stopSafely(e.what());
	}
	catch (const std::exception& e)
	{  // e.g. a device refused a joint limit the plan did not expect
		m.stopSafely(std::string("a device refused a command: ") + e.what());
	}
	m.finish();
	return m.r;
}

size_t countShots(const std::vector<StereoShot>& shots, StereoShot::Purpose purpose)
{
	const auto of_purpose = [&](const StereoShot& s) { return s.purpose == purpose; };
	return static_cast<size_t>(std::count_if(shots.begin(), shots.end(), of_purpose));
}

}  // namespace mrolr::mission
