// mrolr-slam --live: drive the world's waypoints with a simulated stereo head and vision-driven
// EKF-SLAM (thesis 5.6.3, 7.2(a)-(c)).
#include <mrolr/apps/SlamApp.h>
#include <mrolr/geometry/IdealHead.h>
#include <mrolr/util/Config.h>
#include <mrolr/vision/Fixation.h>
#include <mrolr/vision/KnownFeatures.h>
#include <mrolr/vision/SyntheticWorld.h>
#include <mrolr/world/World.h>
#include "KnownAcquisition.h"
#include "LiveHeads.h"
#include "SlamSetup.h"

#include <mrpt/config/CConfigFile.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>

namespace mrolr::apps
{
namespace
{
constexpr int kHomeMeasurements = 3;  ///< measurements of each known feature at the end

/** The true wheels: noisy, and the left wheel slips during bursts. */
class TrueWheels
{
 public:
	explicit TrueWheels(const SlamRunOptions& o) : o_(o), rng_(o.seed) {}
	base::WheelControl perturb(const base::PlannedStep& step)
	{
		base::WheelControl u = step.u;
		std::normal_distribution<double> n01;
		u.v1_mps *= 1 + o_.true_velocity_noise_fraction * n01(rng_);
		u.v2_mps *= 1 + o_.true_velocity_noise_fraction * n01(rng_);
		if (step.kind != base::PlannedStep::Kind::Translate) return u;
		if (burst_left_ == 0 &&
		    std::uniform_real_distribution<double>()(rng_) < o_.slip_burst_probability)
			burst_left_ = o_.slip_burst_length_steps;
		if (burst_left_ > 0) --burst_left_, u.v2_mps *= 1 - o_.slip_fraction;
		return u;
	}

 private:
	SlamRunOptions o_;
	std::mt19937 rng_;
	int burst_left_ = 0;
};

Eigen::Vector3d startPose(const world::World& w)
{
	if (w.waypoints.size() < 2)
		throw std::runtime_error(w.path + ": the route needs at least 2 waypoints");
	return {w.waypoints[0].z_m, w.waypoints[0].x_m, w.waypoints[0].phi_rad};
}

std::string knownFeaturesPath(const world::World& w)
{
	return (std::filesystem::path(w.directory()) / "known_features.ini").string();
}

}  // namespace

void SlamApp::runAcquireKnown(std::ostream& out)
{
	const SlamSetup s = loadSetup(config_path);
	const world::World w = world::World::load(world_path);
	const geometry::BiSightHead head(s.bisight);
	const auto head_device =
	    makeLiveHead(head_kind, w, head, s.run.texture_size_px, s.run.image_noise_grey, s.run.seed);
	LiveHead& device = *head_device;
	const Eigen::Vector3d x0 = startPose(w);
	device.setVehicle(x0);
	const auto known = acquireKnown(w, device, head, s, x0, known_names);
	vision::saveKnownFeatures(knownFeaturesPath(w), known);
	out << "acquired " << known.size() << " known feature(s) into " << knownFeaturesPath(w) << "\n";
}

namespace
{
void addKnownFeatures(vision::VisualSlam& vslam, const world::World& w, LiveHead& device,
                      const geometry::BiSightHead& head, const SlamSetup& s,
                      const Eigen::Vector3d& x0, const std::string& head_kind,
                      const std::vector<std::string>& names)
{
	const std::string path = knownFeaturesPath(w);
	std::vector<vision::KnownFeature> known;
	if (std::filesystem::exists(path)) known = vision::loadKnownFeatures(path);
	// The stored patches come from the synthetic head; the rendered lab looks different, so there
	// the same features are re-acquired by fixation from the start pose.
	if (head_kind != "synthetic" || known.empty())
	{
		std::vector<std::string> ids = names;  // --known, else the file's, else the world's
		if (ids.empty())
			for (const auto& f : known) ids.push_back(f.id);
		known = acquireKnown(w, device, head, s, x0, ids);
	}
	for (const auto& f : known) vslam.addKnownFeature(f.id, f.p_FinW, f.patch);
}
}  // namespace

void SlamApp::runLive()
{
	const SlamSetup s = loadSetup(config_path);
	const world::World w = world::World::load(world_path);
	for (const auto& l : w.landmarks) true_landmarks.push_back({l.name, l.p_LinW});
	run_title = "mrolr-slam: live on world '" +
	            std::filesystem::path(world_path).parent_path().filename().string() + "', seed " +
	            std::to_string(s.run.seed) + ", head " + head_kind;
	const geometry::BiSightHead head(s.bisight);
	const base::LabmateModel model(s.labmate);
	const auto head_device =
	    makeLiveHead(head_kind, w, head, s.run.texture_size_px, s.run.image_noise_grey, s.run.seed);
	LiveHead& device = *head_device;
	const Eigen::Vector3d x0 = startPose(w);
	slam::ActiveSlamFilter filter(s.slam, model);
	filter.reset(x0);
	device.setVehicle(x0);
	vision::VisualSlam vslam(filter, head, s.vision, model);
	addKnownFeatures(vslam, w, device, head, s, x0, head_kind, known_names);
	TrueWheels wheels(s.run);
	Eigen::Vector3d x_true = x0, x_dr = x0;
	auto log = [&](vision::CycleRecord rec, bool at_home = false)
	{
		steps.push_back({x_true,
		                 filter.vehicle(),
		                 x_dr,
		                 filter.vehicleCovariance().diagonal(),
		                 {std::move(rec)},
		                 at_home});
	};
	log(vslam.step({}, device));
	for (size_t k = 1; k < w.waypoints.size(); ++k)
	{
		const auto& wp = w.waypoints[k];
		const auto leg =
		    base::planLeg(filter.vehicle(), {wp.z_m, wp.x_m, wp.phi_rad}, model, s.trajectory);
		for (size_t j = 0; j < leg.size(); ++j)
		{
			x_true = model.move(x_true, wheels.perturb(leg[j]));
			x_dr = model.move(x_dr, leg[j].u);
			device.setVehicle(x_true);
			std::vector<base::WheelControl> upcoming;
			for (size_t n = j + 1; n < leg.size(); ++n) upcoming.push_back(leg[n].u);
			log(vslam.step(leg[j].u, device, upcoming));
		}
	}
	// Back home: re-find the known features (5.6.2), which removes the drift of the route.
	for (size_t i = 0; i < filter.numFeatures(); ++i)
		if (filter.info(i).known)
			for (int k = 0; k < kHomeMeasurements; ++k) log(vslam.measureFeature(i, device), true);
	recordMap(filter, vslam);
	summary.selection = s.vision.selection == vision::Selection::Saccade ? "saccade" : "largest_vs";
}

}  // namespace mrolr::apps
