#pragma once
/** The simulator's shortcut sensors (hw/SimulatedSensors.h), for tests only and never a default:
 *  - `ideal_sim` landmarks: the ideal-head angles (eq 5.40) of the world's landmarks seen from the
 *    true head pose, with Gaussian noise; a landmark is seen within max_range_m, from the front
 *    of its patch and within the head's joint limits. Options `[sim_ideal_landmarks]`.
 *  - `exact_sim` scenes: the exact wire-frames of the objects whose origin the left camera sees,
 *    carried by their true T_OinL and corrupted (endpoint noise, missing and fragmented segments,
 *    hidden back side). Options `[sim_exact_scenes]`.
 * Both read the lab's truth; their random draws follow the run's seed. */
#include <mrolr/hw/SimulatedSensors.h>
#include <mrolr/sim/Lab.h>

#include <mrpt/config/CConfigFileBase.h>

#include <memory>
#include <random>

namespace mrolr::sim
{
struct IdealLandmarkOptions
{
	double std_pan_rad = 0.002, std_elevation_rad = 0.01, std_vergence_rad = 0.002;
	double max_range_m = 8;
	/** Every key optional (these defaults). */
	void loadFromConfigFile(const mrpt::config::CConfigFileBase& cfg, const std::string& section);
};

struct ExactSceneOptions
{
	double endpoint_sigma_mm = 1.0;
	double missing_fraction = 0.15;
	double fragment_probability = 0.1;
	bool hide_back_side = true;
	double max_object_range_m = 2.0;  ///< objects further from the left camera are not seen
	void loadFromConfigFile(const mrpt::config::CConfigFileBase& cfg, const std::string& section);
};

/** A simulated sensor chosen by name (`ideal_sim`); throws std::invalid_argument naming the
 * choices for any other name. */
std::unique_ptr<hw::LandmarkSensor> makeLandmarkSensor(const std::string& name, const Lab& lab,
                                                       const IdealLandmarkOptions& o);
/** A simulated sensor chosen by name (`exact_sim`); throws std::invalid_argument otherwise. */
std::unique_ptr<hw::SceneSensor> makeSceneSensor(const std::string& name, const Lab& lab,
                                                 const ExactSceneOptions& o);

}  // namespace mrolr::sim
