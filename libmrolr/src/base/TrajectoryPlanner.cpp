#include <mrolr/base/TrajectoryPlanner.h>
#include <mrolr/util/OptionsBinder.h>

#include <cmath>
#include <ostream>

namespace mrolr::base
{
namespace
{
using O = TrajectoryOptions;
constexpr auto kOpt = util::Presence::Optional;

const util::OptionsBinder<O>& trajectoryOptionsBinder()
{
	static const auto b = util::OptionsBinder<O>()
	    .number("step_length_m", &O::step_length_m, 1e-3, 100)
	    .number("min_step_m", &O::min_step_m, 1e-4, 100)
	    .number("max_rotation_step_deg", &O::max_rotation_step_deg, 0.1, 360)
	    .number("position_tolerance_m", &O::position_tolerance_m, 0, 10, kOpt);
	return b;
}
}  // namespace

void TrajectoryOptions::loadFromConfigFile(const mrpt::config::CConfigFileBase& cfg,
                                           const std::string& section)
{
	trajectoryOptionsBinder().load(cfg, section, *this);
	util::requireInRange(cfg, section, "min_step_m", min_step_m, 1e-4, step_length_m);
}

void TrajectoryOptions::dumpToTextStream(std::ostream& out) const
{
	out << "[trajectory]\n";
	trajectoryOptionsBinder().dump(out, *this);
}

double wrapAngle(double a)
{
	a = std::remainder(a, 2 * M_PI);
	return a <= -M_PI ? a + 2 * M_PI : a;
}

std::vector<double> translationSteps(double distance_m, const TrajectoryOptions& o)
{
	std::vector<double> steps;
	double r = distance_m;
	const double eps = 1e-9;
	while (r >= o.step_length_m - eps)
	{
		steps.push_back(o.step_length_m);
		r -= o.step_length_m;
	}
	while (r >= o.min_step_m)
	{
		steps.push_back(r / 2);
		r -= r / 2;
	}
	if (r > eps) steps.push_back(r);
	return steps;
}

std::vector<double> rotationSteps(double angle_rad, const TrajectoryOptions& o)
{
	if (angle_rad == 0) return {};
	const double max_rad = o.max_rotation_step_deg * M_PI / 180;
	const int n = static_cast<int>(std::ceil(std::abs(angle_rad) / max_rad - 1e-12));
	return std::vector<double>(std::max(n, 1), angle_rad / std::max(n, 1));
}

namespace
{
void appendRotation(std::vector<PlannedStep>& plan, double angle, const LabmateModel& m,
                    const TrajectoryOptions& o)
{
	for (double a : rotationSteps(angle, o))
		plan.push_back({PlannedStep::Kind::Rotate, a, m.rotationControl(a)});
}
}  // namespace

std::vector<PlannedStep> planLeg(const Eigen::Vector3d& from, const Eigen::Vector3d& to,
                                 const LabmateModel& model, const TrajectoryOptions& o)
{
	std::vector<PlannedStep> plan;
	const double dz = to[0] - from[0], dx = to[1] - from[1];
	const double dist = std::hypot(dz, dx);
	double heading = from[2];
	if (dist > o.position_tolerance_m)
	{
		heading = std::atan2(dx, dz);
		appendRotation(plan, wrapAngle(heading - from[2]), model, o);
		for (double d : translationSteps(dist, o))
			plan.push_back({PlannedStep::Kind::Translate, d, model.translationControl(d)});
	}
	appendRotation(plan, wrapAngle(to[2] - heading), model, o);
	return plan;
}

}  // namespace mrolr::base
