// The simulated lab and its shortcut sensors, built for an app from a mission file.
#include <mrolr/apps/SimulatedWorld.h>
#include <mrolr/sim/SimulatedSensors.h>
#include <mrolr/util/Config.h>

namespace mrolr::apps
{
namespace
{
sim::LabOptions labOptions(const mrpt::config::CConfigFileBase& cfg, const std::string& dir,
                           const std::string& world_file)
{
	if (world_file.empty() && !sim::LabOptions::namesWorld(cfg))
		throw util::ConfigError(util::describeKey(cfg, "simulator", "world_file") +
		                        ": missing: the simulator needs a world (or give --world)");
	return sim::LabOptions::load(cfg, dir, world_file);
}

template <typename Make>
auto sensor(const mrpt::config::CConfigFileBase& cfg, const char* section, const char* key,
            Make make)
{
	try
	{
		return make();
	}
	catch (const std::invalid_argument& e)
	{
		throw util::ConfigError(util::describeKey(cfg, section, key) + ": " + e.what());
	}
}
}  // namespace

SimulatedWorld::SimulatedWorld(const mrpt::config::CConfigFileBase& cfg,
                               const std::string& base_dir, const mission::MissionOptions& o,
                               const std::string& world_file)
    : lab_(std::make_unique<sim::Lab>(labOptions(cfg, base_dir, world_file)))
{
	using mission::LandmarkSource;
	using mission::SceneSource;
	if (o.navigation.landmark_source == LandmarkSource::Simulated)
	{
		sim::IdealLandmarkOptions lo;
		lo.loadFromConfigFile(cfg, "sim_ideal_landmarks");
		landmarks_ = sensor(cfg, "navigation", "landmark_sensor", [&]
		                    { return sim::makeLandmarkSensor(o.navigation.landmark_sensor, *lab_, lo); });
	}
	if (o.search.scene_source == SceneSource::Simulated)
	{
		sim::ExactSceneOptions so;
		so.loadFromConfigFile(cfg, "sim_exact_scenes");
		scenes_ = sensor(cfg, "search", "scene_sensor",
		                 [&] { return sim::makeSceneSensor(o.search.scene_sensor, *lab_, so); });
	}
}

SimulatedWorld::~SimulatedWorld() = default;

mission::SimDevices SimulatedWorld::devices()
{
	return {&lab_->base(), &lab_->head(), &lab_->arm()};
}

mission::SimulatedSensors SimulatedWorld::sensors()
{
	return {landmarks_.get(), scenes_.get()};
}

bool SimulatedWorld::needed(const mission::MissionOptions& o)
{
	return o.devices.anySim() ||
	       o.navigation.landmark_source == mission::LandmarkSource::Simulated ||
	       o.search.scene_source == mission::SceneSource::Simulated;
}

}  // namespace mrolr::apps
