#pragma once
/** Where an app joins the robot side and the world side: the simulated lab built from the world
 * side's sections of a mission file (sim::LabOptions), the simulator's shortcut sensors that the
 * mission file names (never by default), and the lab's devices handed to the robot. Only apps
 * build this; the robot side sees only the hw:: interfaces. */
#include <mrolr/mission/MissionDevices.h>
#include <mrolr/mission/MissionOptions.h>
#include <mrolr/sim/Lab.h>

#include <mrpt/config/CConfigFileBase.h>

#include <memory>
#include <string>

namespace mrolr::apps
{
class SimulatedWorld
{
 public:
	/** Builds the lab of @p world_file (empty: `[simulator] world_file` of @p cfg) and the
	 * simulated sensors @p o names. Throws util::ConfigError naming the key (no world, an
	 * unknown sensor name). */
	SimulatedWorld(const mrpt::config::CConfigFileBase& cfg, const std::string& base_dir,
	               const mission::MissionOptions& o, const std::string& world_file = "");
	~SimulatedWorld();
	sim::Lab& lab() { return *lab_; }
	mission::SimDevices devices();
	mission::SimulatedSensors sensors();

	/** True when @p o needs a simulator: a device or the camera with `driver = sim`, or a
	 * simulated sensor. */
	static bool needed(const mission::MissionOptions& o);

 private:
	std::unique_ptr<sim::Lab> lab_;
	std::unique_ptr<hw::LandmarkSensor> landmarks_;
	std::unique_ptr<hw::SceneSensor> scenes_;
};

}  // namespace mrolr::apps
