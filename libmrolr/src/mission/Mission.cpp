// The mission's state machine (thesis fig 5.8.1.5) on the robot's devices.
#include <mrolr/geometry/Frames.h>
#include <mrolr/geometry/GeometryError.h>
#include <mrolr/hw_serial/SerialError.h>
#include <mrolr/mission/DecisionLog.h>
#include <mrolr/mission/Mission.h>
#include "MissionImpl.h"
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

Mission::Impl::Impl(const MissionOptions& opts, RobotDevices d, SimulatedSensors s)
    : o(opts), dev(checked(std::move(d))), sensors(s)
{
	requireSensors(o, sensors);
}

void Mission::Impl::loadTarget()
{
	r.timeline.beginStage("load_target");
	ComputeTimer t(r.timeline);
	const auto file = (std::filesystem::path(o.models_dir) / (o.target + ".wf")).string();
	target = model::loadWireFrame(file);
	ViewSource views = [this](const geometry::HeadAngles& a) { return reconstructedView(a); };
	if (o.search.scene_source == SceneSource::Simulated)
		views = [this](const geometry::HeadAngles& a) { return simulatedView(a); };
	// the rest of the database ([search] behind_found, rival_models)
	std::vector<std::string> files;
	if ((o.search.behind_found || o.search.rival_models) && o.search.image_verification)
		for (const auto& e : std::filesystem::directory_iterator(o.models_dir))
			if (e.path().extension() == ".wf" && e.path().stem() != o.target)
				files.push_back(e.path().string());
	std::sort(files.begin(), files.end());  // the same order on every machine
	std::vector<model::WireFrame> others;
	for (const auto& f : files) others.push_back(model::loadWireFrame(f));
	search = std::make_unique<ObjectSearch>(o, target, views, others);
	r.timeline.note("target model " + o.target + " (" + file + "): " +
	                std::to_string(target.lines.size()) + " lines, " +
	                std::to_string(target.conics.size()) + " conics" +
	                (others.empty() ? std::string()
	                                : ", " + std::to_string(others.size()) + " other models"));
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
		catch (const hw::DeviceFailure&)
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
	obstacles->ignoreSelf(*self);
	attachObstacleAvoidance(*nav, *obstacles, o);
}

void Mission::Impl::navigate()
{
	r.timeline.beginStage("navigate");
	nav = std::make_unique<Navigator>(o, *dev.base, r.timeline);
	self = std::make_unique<SelfModel>(o.rtx, o.grasp, o.marker, o.dock.T_C0inA,
	                                   geometry::BiSightHead(o.bisight));
	self->setJoints(dev.arm->joints());
	nav->on_step = [this](const PathSample& s)
	{
		if (progress && *progress) (*progress)(r.timeline.stage(), s);
		if (decisions) decisions->estimate(s);
	};
	if (decisions)
		nav->on_measurement = [this](const vision::CycleRecord& c) { decisions->measurement(c); };
	nav->stop_requested = [this] { return stop_flag && stop_flag->load(); };
	if (o.obstacle_mode) attachObstacleMode();
	r.navigation_source = o.navigation.landmark_sensor;
	if (o.mode == NavigationMode::Slam && o.navigation.landmark_source == LandmarkSource::Images)
	{
		nav_head = std::make_unique<MissionStereoHead>(*dev.head);
		nav->useImages(*nav_head, [this] { return nav_head->grabSeconds(); });
		nav->ignoreSelf(*self);
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
	if (r.search.found && decisions) decisions->recognised(r.search, r.search_xv_estimate, target);
	return r.search.found;
}

void Mission::Impl::goHome()
{
	r.timeline.beginStage("return_home");
	self->setJoints(dev.arm->joints());  // the arm holds the object up, or stands parked
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
	parked = dev.arm->joints();
	navigate();
	for (const auto& station : o.plan.stations)
		if ((r.found = searchStation(station))) break;
	if (r.found) retrieve();
	goHome();
	if (r.retrieved && !r.place.placed)  // in the gripper all the way: its jaws still tell
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
	m.decisions = decisions;
	if (decisions) m.r.timeline.on_note = [this](const TimelineEvent& e) { decisions->note(e); };
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
	catch (const hw::ReplayDivergence& e)
	{  // a replay asked for what its recording does not hold: stop there, naming it
		m.r.divergence = "in stage " + m.r.timeline.stage() + ": " + e.what();
		m.stopSafely(m.r.divergence);
	}
	catch (const hw::DeviceFailure& e)
	{  // a device stopped answering: stop where we are, keep what was recorded
		m.stopSafely(e.what());
	}
	catch (const std::exception& e)
	{  // e.g. a device refused a joint limit the plan did not expect
		m.stopSafely(std::string("a device refused a command: ") + e.what());
	}
	m.finish();
	m.r.timeline.on_note = nullptr;  // the result outlives this mission's decision log
	return m.r;
}

size_t countShots(const std::vector<StereoShot>& shots, StereoShot::Purpose purpose)
{
	const auto of_purpose = [&](const StereoShot& s) { return s.purpose == purpose; };
	return static_cast<size_t>(std::count_if(shots.begin(), shots.end(), of_purpose));
}

}  // namespace mrolr::mission
