#pragma once
/** The world's truth about a run, as eval receives it after the run: in-process from the
 * simulated lab (every step's true pose and every camera frame's truth), or from the emulator's
 * T.json in two-process runs (the final vehicle pose, the objects and what the gripper holds).
 * W: x left, y up, z forward, metres. */
#include <mrolr/sim/Lab.h>

#include <nlohmann/json.hpp>

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace mrolr::eval
{
struct ObjectTruth
{
	std::string name, model;
	Eigen::Isometry3d T_OinW_start = Eigen::Isometry3d::Identity();  ///< where the world put it
	Eigen::Isometry3d T_OinW = Eigen::Isometry3d::Identity();        ///< at the end
	/** The turns about O's z that map the object's shape onto itself, in degrees ({-1}: every
	 * angle, a body of revolution; symmetryAnglesDeg): a pose error is taken modulo them. */
	std::vector<double> symmetry_deg = {0};
};

struct ContactTruth
{
	std::string what;                                  ///< `wall`, `table.NAME`, `obstacle.NAME`
	Eigen::Vector2d p_zx = Eigen::Vector2d::Zero();    ///< contact point in W
};

struct MissionTruth
{
	Eigen::Vector3d final_zxphi = Eigen::Vector3d::Zero();
	std::vector<ObjectTruth> objects;
	std::string held;  ///< instance in the gripper, "" for none
	std::vector<std::string> on_board;  ///< instances let go of over the robot's deck
	std::optional<ContactTruth> contact;
	/** What the gripper did to the world (pushes, falls, grips, a table), in order. */
	std::vector<sim::GripperEvent> gripper_events;
	/** In-process only: every step and every camera frame (empty from T.json). */
	std::vector<sim::TruthLog::Step> steps;
	std::vector<sim::TruthLog::Frame> frames;
	/** The arm's physical mount T_C0inA (mm): the nominal off by the dock's error; for the true
	 * grasp and the dock calibration's error. */
	std::optional<Eigen::Isometry3d> T_C0inA_mm;
	/** In-process only: the world, for the pictures. */
	std::shared_ptr<const world::World> world;
};

/** The truth of @p lab now (after the run). */
MissionTruth truthOf(const sim::Lab& lab);
/** T.json: `{"vehicle": {"z_m", "x_m", "phi_deg"}, "objects": [{"name", "model", "T_OinW",
 * "T_OinW_start", "symmetry_deg"}], "held": NAME or null, "on_board": [NAME…], "contact":
 * {"what", "z_m", "x_m"} or null, "gripper_events": [{"kind", "object", "detail"}], "frames":
 * [{"frame", "T_C0inW", "objects": {NAME: T_OinW}}]}` ("on_board", "gripper_events", "frames"
 * and an object's "symmetry_deg" optional on reading). */
nlohmann::json truthJson(const MissionTruth& t);
/** The gripper's events as a JSON list of {"kind", "object", "detail"}. */
nlohmann::json gripperEventsJson(const std::vector<sim::GripperEvent>& events);
/** Reads T.json; throws std::runtime_error naming @p source and the field that is wrong. */
MissionTruth truthFromJson(const nlohmann::json& j, const std::string& source);

}  // namespace mrolr::eval
