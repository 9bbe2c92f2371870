#pragma once
/** Waypoint-to-waypoint motion of the Labmate as used in the thesis (5.6.3, 7.2.1): rotate in place
 * towards the next waypoint, translate in fixed steps (20 cm) whose last step is halved until the
 * remainder is under 32 mm, then rotate in place to the waypoint's heading. The filter measures
 * after every step. Poses are (z, x, φ) in W as in LabmateModel.h. */

#include <mrolr/base/LabmateModel.h>

#include <mrpt/config/CConfigFileBase.h>

#include <Eigen/Core>

#include <iosfwd>
#include <string>
#include <vector>

namespace mrolr::base
{
/** Step sizes of the planner, section [trajectory] of config/labmate.ini. */
struct TrajectoryOptions
{
	double step_length_m = 0.20;         ///< full translation step (5.6.1)
	double min_step_m = 0.032;           ///< halving stops once the remainder is below this (7.2.1)
	double max_rotation_step_deg = 180;  ///< rotations larger than this are split into equal steps
	double position_tolerance_m = 1e-3;  ///< legs shorter than this skip the first rotation

	void loadFromConfigFile(const mrpt::config::CConfigFileBase& cfg, const std::string& section);
	void dumpToTextStream(std::ostream& out) const;
};

/** One planned motion step: a rotation in place or a straight translation, and its control. */
struct PlannedStep
{
	enum class Kind
	{
		Rotate,
		Translate
	};
	Kind kind = Kind::Translate;
	double amount = 0;  ///< rotation in rad (positive towards x) or distance in m
	WheelControl u;
};

/** The translation step lengths for a straight move of @p distance_m ≥ 0: full steps while the
 * remainder is at least a full step, then halves of the remainder while it is at least
 * min_step_m, then the remainder (7.2.1: 1.49 m → 7 × 0.2, 0.045, 0.0225, 0.0225). */
std::vector<double> translationSteps(double distance_m, const TrajectoryOptions& options);

/** The rotation steps (rad) for a rotation in place by @p angle_rad, each at most
 * max_rotation_step_deg. */
std::vector<double> rotationSteps(double angle_rad, const TrajectoryOptions& options);

/** Rotate–translate–rotate from pose @p from to waypoint pose @p to (both (z, x, φ) in W). */
std::vector<PlannedStep> planLeg(const Eigen::Vector3d& from, const Eigen::Vector3d& to,
                                 const LabmateModel& model, const TrajectoryOptions& options);

/** The angle wrapped into (−π, π]. */
double wrapAngle(double angle_rad);

}  // namespace mrolr::base
