// The mission's state machine (thesis fig 5.8.1.5) on the devices of the mission's factory.
#include <mrolr/geometry/Frames.h>
#include <mrolr/geometry/GeometryError.h>
#include <mrolr/hw_serial/SerialError.h>
#include <mrolr/mission/Mission.h>
#include <mrolr/mission/MissionDevices.h>
#include <mrolr/mission/MissionStereoHead.h>
#include <mrolr/mission/ObstacleAvoidance.h>
#include <mrolr/model/SceneModel.h>
#include <mrolr/sim/ObjectWireFrame.h>
#include <mrolr/sim/SceneBuilder.h>
#include <mrolr/stereo/HeadCalibration.h>
#include <mrolr/world/ObjectShape.h>

#include <chrono>
#include <cmath>

namespace mrolr::mission
{
namespace
{
std::map<std::string, model::WireFrame> loadModels(const MissionOptions& o)
{
	std::map<std::string, model::WireFrame> out;
	for (const auto& [name, shape] : sim::loadObjectShapes(o.world))
		out[name] = sim::objectWireFrame(shape);
	if (!out.count(o.target))
		out[o.target] = sim::objectWireFrame(world::ObjectShape::load(o.target_model_file));
	return out;
}

NamedPose waypoint(const MissionOptions& o, const std::string& name)
{
	const auto* w = o.world.findWaypoint(name);
	return {w->name, {w->z_m, w->x_m, w->phi_rad}};
}

Eigen::Isometry3d metres(Eigen::Isometry3d T_mm)
{
	T_mm.translation() /= 1000.0;
	return T_mm;
}

std::shared_ptr<SimulatedLab> labFor(const MissionOptions& o, std::shared_ptr<SimulatedLab> lab)
{
	return lab ? lab : std::make_shared<SimulatedLab>(o);
}
}  // namespace

struct Mission::Impl
{
	const MissionOptions& o;
	MissionResult r;
	std::map<std::string, model::WireFrame> models;
	std::shared_ptr<SimulatedLab> lab;                ///< the truth behind the devices
	MissionDevices dev;                               ///< sim or serial (driver = ...)
	std::map<std::string, Eigen::Isometry3d>& poses;  ///< true object poses (the arm moves them)
	sim::SimBase& base;                               ///< the true base (truth only, no commands)
	std::mt19937 rng;
	std::unique_ptr<Navigator> nav;
	std::unique_ptr<ObjectSearch> search;
	std::unique_ptr<ObstacleAvoidance> obstacles;  ///< obstacle mode
	std::unique_ptr<MissionStereoHead> nav_head;   ///< measurement_source = images
	std::function<void(const std::string&, const PathSample&)>* progress = nullptr;
	bool render_failed = false;
	std::string carried;  ///< instance standing on the base after retrieval
	Eigen::Isometry3d T_OinC0_carried = Eigen::Isometry3d::Identity();  ///< m

	Impl(const MissionOptions& opts, std::shared_ptr<SimulatedLab> simulated)
	    : o(opts),
	      lab(labFor(opts, std::move(simulated))),
	      dev(opts.devices, *lab),
	      poses(lab->objectPoses()),
	      base(lab->base()),
	      rng(opts.seed + 7)
	{
	}
	Eigen::Isometry3d trueC0() const { return lab->trueC0(); }
	WorldObjects objects() const
	{
		WorldObjects out;
		for (const auto& p : o.world.objects) out[p.name] = {p.model, poses.at(p.name)};
		return out;
	}
	void lookAt(const geometry::HeadAngles& angles);
	hw::StereoImages grabStereo();
	void attachObstacleMode();
	ObjectSearch::StereoScene reconstructedScene(const geometry::HeadAngles& angles);
	void stopSafely(const std::string& why);
	void runStages();
	void loadTarget();
	void navigate();
	bool searchStation(const NamedPose& station);
	void retrieve();
	void goHome();
	void finish();
	double tableHeightNear(const Eigen::Vector3d& p_W) const;
	std::optional<Eigen::Isometry3d> reobserveAt(const Eigen::Isometry3d& T_OinC0_mm);
	void compareVerificationWithTruth(const Retrieval& retrieval);
};

void Mission::Impl::loadTarget()
{
	r.timeline.beginStage("load_target");
	ComputeTimer t(r.timeline);
	models = loadModels(o);
	search = std::make_unique<ObjectSearch>(o, models.at(o.target), models);
	search->on_view = [this](const geometry::HeadAngles& a) { lookAt(a); };
	if (o.search.scene_source == "reconstructed")
		search->scene_from_stereo = [this](const geometry::HeadAngles& a)
		{ return reconstructedScene(a); };
	r.timeline.note("target model " + o.target + ": " +
	                std::to_string(models.at(o.target).lines.size()) + " lines, " +
	                std::to_string(models.at(o.target).conics.size()) + " conics");
}

void Mission::Impl::lookAt(const geometry::HeadAngles& angles)
{
	dev.head().moveTo(angles);
	// A reconstructed view grabs (and records) its own pair.
	const bool reconstructed = o.search.scene_source == "reconstructed";
	if (!o.search.render_stereo || render_failed || reconstructed) return;
	try
	{
		grabStereo();
	}
	catch (const hw::SerialDeviceError&)
	{
		throw;  // the head stopped answering: the mission stops
	}
	catch (const std::exception& e)
	{  // the recording loses its images, the mission goes on (and says so)
		r.timeline.note(std::string("stereo rendering failed, no more images: ") + e.what());
		render_failed = true;
	}
}

hw::StereoImages Mission::Impl::grabStereo()
{
	const auto t0 = std::chrono::steady_clock::now();
	auto images = dev.head().grab();
	StereoShot shot{nav->path().back(), images.angles, images.left, images.right};
	shot.state.time_s = r.timeline.simulatedSeconds();
	r.shots.push_back(std::move(shot));
	r.timeline.addRender(
	    std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
	return images;
}

/** The scene of a view reconstructed from a new stereo pair (scene_source = reconstructed), with
 * the pair's edges for image verification ([search] image_verification). */
ObjectSearch::StereoScene Mission::Impl::reconstructedScene(const geometry::HeadAngles& angles)
{
	dev.head().moveTo(angles);
	const auto images = grabStereo();
	ComputeTimer t(r.timeline);
	const auto calib = stereo::calibrationFromHead(geometry::BiSightHead(o.bisight), images.angles);
	const cv::Mat left = images.left.asCvMat<cv::Mat>(mrpt::img::SHALLOW_COPY);
	const cv::Mat right = images.right.asCvMat<cv::Mat>(mrpt::img::SHALLOW_COPY);
	ObjectSearch::StereoScene view{
	    model::sceneToWireFrame(stereo::reconstructScene(left, right, calib, o.scene)), {}};
	if (o.search.image_verification)
		view.images =
		    std::make_shared<recog::ImageVerifier>(left, right, calib, o.image_verification);
	return view;
}

void Mission::Impl::attachObstacleMode()
{
	auto look = [this](const geometry::HeadAngles& a)
	{
		dev.head().moveTo(a);
		return grabStereo();
	};
	obstacles = std::make_unique<ObstacleAvoidance>(geometry::BiSightHead(o.bisight), o.obstacle,
	                                                look, r.timeline);
	obstacles->setKnownTables(o.world.tables, o.obstacle.table_margin_m);
	nav->max_detours_per_leg = o.obstacle.max_detours_per_leg;
	nav->before_translation = [this](const Eigen::Vector3d& e, const Eigen::Vector3d& goal)
	{ return obstacles->check(e, goal); };
}

void Mission::Impl::navigate()
{
	r.timeline.beginStage("navigate");
	nav = std::make_unique<Navigator>(
	    o, dev.base(), [this] { return base.truePose(); }, r.timeline);
	nav->on_step = [this](const PathSample& s)
	{
		if (!carried.empty()) poses[carried] = trueC0() * T_OinC0_carried;
		if (progress && *progress) (*progress)(r.timeline.stage(), s);
	};
	if (o.obstacle_mode) attachObstacleMode();
	if (o.mode == NavigationMode::Slam && o.navigation.measurement_source == "images")
	{
		nav_head = std::make_unique<MissionStereoHead>(dev.head());
		nav->useImages(*nav_head, [this] { return nav_head->grabSeconds(); });
	}
	for (size_t i = 1; i < o.route.size(); ++i) nav->driveTo(waypoint(o, o.route[i]));
}

bool Mission::Impl::searchStation(const NamedPose& station)
{
	r.timeline.beginStage("navigate");
	nav->driveTo(station);
	r.timeline.beginStage("search");
	++r.stations_searched;
	r.search = search->sweep(objects(), trueC0(), rng, r.timeline);
	r.search_xv_true = base.truePose();
	r.timeline.note(station.name + ": " + (r.search.found ? "found" : "not found"));
	if (r.search.found) r.found_at_station = station.name;
	return r.search.found;
}

double Mission::Impl::tableHeightNear(const Eigen::Vector3d& p_W) const
{
	double best = 1e9, h = 0;
	for (const auto& t : o.world.tables)
		if (const double d = std::hypot(t.z_m - p_W.z(), t.x_m - p_W.x()); d < best)
			best = d, h = t.top_height_m;
	return h;
}

void Mission::Impl::retrieve()
{
	r.timeline.beginStage("retrieve");
	// Simulated docking: the arm base stands at the known T_C0inA from the true head centre.
	lab->dockArm();
	const auto& arm = lab->arm();  // truth: what the gripper holds
	auto reobserve = [&](const Eigen::Isometry3d& T_OinC0_mm) -> std::optional<Eigen::Isometry3d>
	{ return reobserveAt(T_OinC0_mm); };
	const Eigen::Vector3d p_OinW = (trueC0() * metres(r.search.T_OinC0)).translation();
	Retrieval retrieval(o, models.at(o.target));
	r.retrieval = retrieval.run(
	    r.search.T_OinC0, tableHeightNear(p_OinW), dev.arm(), reobserve,
	    [&] { return arm.grasped(); }, r.timeline);
	compareVerificationWithTruth(retrieval);
	r.retrieved = r.retrieval.retrieved && arm.grasped() == r.search.instance;
	if (!r.retrieval.feasible) r.failure = "grasp not feasible: " + r.retrieval.reasons.front();
	if (!r.retrieved) return;
	// The arm puts the object on the base's deck (thesis 7.2.2): 0.2 m behind and 0.5 m below C0.
	carried = arm.grasped();
	T_OinC0_carried = trueC0().inverse() * poses.at(carried);
	T_OinC0_carried.translation() = Eigen::Vector3d(0, -0.5, -0.2);
	poses[carried] = trueC0() * T_OinC0_carried;
	r.timeline.advance(2 * o.retrieval.arm_move_time_s);
	r.timeline.note("object " + carried + " placed on the base");
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
	lookAt(angles);
	const auto s = search->observe(objects(), trueC0(), angles, rng, r.timeline);
	r.timeline.note(std::string("verification view (object fixated): ") +
	                (s.found ? "recognised" : "not recognised"));
	return s.found ? std::optional(s.T_OinC0) : std::nullopt;
}

void Mission::Impl::compareVerificationWithTruth(const Retrieval& retrieval)
{
	auto& g = r.retrieval;
	if (r.search.instance.empty() || !g.feasible) return;
	const Eigen::Isometry3d& T_true = r.search.T_OinC0_true;
	g.object_error_before_mm = (g.T_OinC0_first.translation() - T_true.translation()).norm();
	if (g.verified)
		g.object_error_after_mm = (g.T_OinC0_verified.translation() - T_true.translation()).norm();
	const Eigen::Isometry3d T_GinA_true = retrieval.graspAt(T_true, g.grasp_turn_deg);
	g.grasp_error_mm = (g.T_GinA.translation() - T_GinA_true.translation()).norm();
}

void Mission::Impl::goHome()
{
	r.timeline.beginStage("return_home");
	nav->driveTo(waypoint(o, o.home_waypoint));
	r.timeline.endStage();
}

void Mission::Impl::finish()
{
	r.home = waypoint(o, o.home_waypoint).xv_zxphi;
	const Eigen::Vector3d truth = base.truePose();
	r.final_position_error_m = (truth.head<2>() - r.home.head<2>()).norm();
	r.final_heading_error_deg = std::abs(base::wrapAngle(truth.z() - r.home.z())) * 180 / M_PI;
	r.dead_reckoning_error_m = (base.odometry().xv_zxphi.head<2>() - truth.head<2>()).norm();
	r.returned_home = r.final_position_error_m <= o.home_tolerance_m;
	r.links = dev.links();
	r.final_objects = objects();
	if (obstacles) r.obstacle = obstacles->report();
	if (nav)  // no device I/O here: a device may have failed
	{
		r.path = nav->path();
		r.final_estimate_error_m = (r.path.back().estimate.head<2>() - truth.head<2>()).norm();
		r.map = nav->map();
		r.measurements = nav->measurements;
		r.measurements_rejected = nav->rejected;
		r.measurements_lost = nav->lost;
		r.features_deleted = nav->deleted_features;
		r.image_searches = nav->image_cycles;
		r.image_matches = nav->image_matched;
	}
	if (nav_head) r.navigation_pairs = nav_head->grabs();
	r.success = r.found && r.retrieved && r.returned_home && !r.stopped;
	if (r.failure.empty() && !r.found)
		r.failure = "target '" + o.target + "' not found at any of " +
		            std::to_string(r.stations_searched) + " search stations";
	if (r.failure.empty() && !r.returned_home) r.failure = "did not return home within tolerance";
}

void Mission::Impl::runStages()
{
	loadTarget();
	navigate();
	for (const auto& station : o.stations)
		if ((r.found = searchStation(station))) break;
	if (r.found)
	{
		r.found_instance = r.search.instance;
		retrieve();
	}
	goHome();
}

void Mission::Impl::stopSafely(const std::string& why)
{
	r.stopped = true;
	r.failure = "stopped: " + why;
	r.timeline.note(r.failure);
	// Steps are discrete (the base stands still between them); a zero step makes sure of it.
	try
	{
		dev.base().step({0, 0, 0});
		r.timeline.note("base stopped");
	}
	catch (const std::exception& stop_error)
	{
		r.timeline.note(std::string("could not command the base to stop: ") + stop_error.what());
	}
	r.timeline.endStage();
}

Mission::Mission(const MissionOptions& o, std::shared_ptr<SimulatedLab> lab)
    : impl_(std::make_unique<Impl>(o, std::move(lab)))
{
}
Mission::~Mission() = default;

MissionResult Mission::run()
{
	auto& m = *impl_;
	m.progress = &on_progress;
	m.r.target = m.o.target;
	try
	{
		m.runStages();
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

}  // namespace mrolr::mission
