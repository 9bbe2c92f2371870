#pragma once
/** Sensors that only a simulator has, for tests that want a shortcut past perception: the
 * ideal-head angles of named landmarks (eq 5.40, `[navigation] landmark_sensor = ideal_sim`) and
 * the exact wire-frames of the objects in view (`[search] scene_sensor = exact_sim`). A real robot
 * has neither: they read the world's truth. They live behind these interfaces so that the robot
 * side never includes the simulator; the world side (area sim) implements them, and an app joins
 * the two only when a configuration names them (never by default). */
#include <mrolr/geometry/BiSightHead.h>
#include <mrolr/model/WireFrame.h>

#include <Eigen/Core>

#include <optional>
#include <string>
#include <vector>

namespace mrolr::hw
{
/** Ideal-head measurements (pan, elevation, vergence; eq 5.40, radians) of named landmarks. */
class LandmarkSensor
{
 public:
	virtual ~LandmarkSensor() = default;
	struct Sighting
	{
		std::string name;
		Eigen::Vector3d h;  ///< measured ideal-head angles, rad
	};
	/** Every landmark the head could fixate now, each with a measurement. */
	virtual std::vector<Sighting> visible() = 0;
	/** A new measurement of landmark @p name, or nothing when it cannot be seen now. */
	virtual std::optional<Eigen::Vector3d> measure(const std::string& name) = 0;
};

/** The scene wire-frame (left camera L, mm) of the view at @p angles. */
class SceneSensor
{
 public:
	virtual ~SceneSensor() = default;
	virtual model::WireFrame scene(const geometry::HeadAngles& angles) = 0;
};

}  // namespace mrolr::hw
