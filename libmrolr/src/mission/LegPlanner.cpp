// Legs that may drive backwards (docs/mission.md "Navigation"): a goal a short way behind the robot
// is reached without turning round, so the head keeps the features it has mapped ahead in view.
#include <mrolr/mission/Navigator.h>

#include <cmath>

namespace mrolr::mission
{
namespace
{
void appendRotation(std::vector<base::PlannedStep>& plan, double angle_rad,
                    const base::LabmateModel& model, const base::TrajectoryOptions& o)
{
	for (double a : base::rotationSteps(angle_rad, o))
		plan.push_back({base::PlannedStep::Kind::Rotate, a, model.rotationControl(a)});
}

/** True when the goal (z, x in W) lies behind the pose @p from and within @p reverse_max_m. */
bool reverseTo(const Eigen::Vector3d& from, const Eigen::Vector3d& to, double reverse_max_m)
{
	const Eigen::Vector2d d = to.head<2>() - from.head<2>();
	const Eigen::Vector2d forward(std::cos(from.z()), std::sin(from.z()));  // z, x components
	return d.norm() <= reverse_max_m && d.dot(forward) < 0;
}
}  // namespace

std::vector<base::PlannedStep> planMissionLeg(const Eigen::Vector3d& from,
                                              const Eigen::Vector3d& to,
                                              const base::LabmateModel& model,
                                              const base::TrajectoryOptions& o,
                                              double reverse_max_m)
{
	const double dist = (to.head<2>() - from.head<2>()).norm();
	if (dist <= o.position_tolerance_m || !reverseTo(from, to, reverse_max_m))
		return base::planLeg(from, to, model, o);
	// Face away from the goal, back up to it in the usual steps, turn to the goal's heading.
	const double heading = std::atan2(from.y() - to.y(), from.x() - to.x());
	std::vector<base::PlannedStep> plan;
	appendRotation(plan, base::wrapAngle(heading - from.z()), model, o);
	for (double d : base::translationSteps(dist, o))
		plan.push_back({base::PlannedStep::Kind::Translate, -d, model.translationControl(-d)});
	appendRotation(plan, base::wrapAngle(to.z() - heading), model, o);
	return plan;
}

}  // namespace mrolr::mission
