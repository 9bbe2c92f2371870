#include <mrolr/arm/GraspFeasibility.h>
#include <mrolr/util/OptionsBinder.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <ostream>
#include <sstream>

namespace mrolr::arm
{
namespace
{
void sampleLine(const model::Line3& l, const Eigen::Isometry3d& T, double step,
                std::vector<Eigen::Vector3d>& out)
{
	const int n = std::max(1, static_cast<int>(std::ceil(l.length() / step)));
	for (int i = 0; i <= n; ++i) out.push_back(T * (l.p1 + (l.p2 - l.p1) * (double(i) / n)));
}

void sampleConic(const model::Conic3& c, const Eigen::Isometry3d& T, double step,
                 std::vector<Eigen::Vector3d>& out)
{
	const double span = std::abs(c.t2 - c.t1);
	const int n = std::max(1, static_cast<int>(std::ceil(span * std::max(c.a, c.b) / step)));
	for (int i = 0; i <= n; ++i)
		out.push_back(T * c.pointAt(c.t1 + (c.t2 - c.t1) * (double(i) / n)));
}

/** Extent along y_G of the object points the open fingers straddle on the way in (within the finger
 * width, from the start of the approach down to the fingertips) and the largest |y_G|; no point →
 * width = −1. */
std::pair<double, double> widthBetweenFingers(const Eigen::Isometry3d& T_AinG,
                                              const std::vector<Eigen::Vector3d>& pts,
                                              const GraspFeasibilityOptions& o)
{
	double lo = std::numeric_limits<double>::infinity(), hi = -lo, far = 0;
	for (const auto& p : pts)
	{
		const Eigen::Vector3d q = T_AinG * p;
		const bool straddled = std::abs(q.x()) <= o.finger_width_mm / 2 &&
		                       q.z() <= o.finger_length_mm / 2 &&
		                       q.z() >= -o.finger_length_mm / 2 - o.approach_distance_mm;
		if (!straddled) continue;
		lo = std::min(lo, q.y());
		hi = std::max(hi, q.y());
		far = std::max(far, std::abs(q.y()));
	}
	return {hi >= lo ? hi - lo : -1.0, far};
}

/** Lowest z_A of the four open fingertips at the grasp and at the start of the approach. */
double lowestFingertip(const Eigen::Isometry3d& T_GinA, const GraspFeasibilityOptions& o)
{
	double low = std::numeric_limits<double>::infinity();
	for (double back : {0.0, o.approach_distance_mm})
		for (double sx : {-1.0, 1.0})
			for (double sy : {-1.0, 1.0})
			{
				const Eigen::Vector3d tip(sx * o.finger_width_mm / 2,
				                          sy * o.gripper_opening_max_mm / 2,
				                          o.finger_length_mm / 2 - back);
				low = std::min(low, (T_GinA * tip).z());
			}
	return low;
}

int pointsInSweptBox(const Eigen::Isometry3d& T_AinG, const std::vector<Eigen::Vector3d>& pts,
                     const GraspFeasibilityOptions& o)
{
	const double c = o.neighbour_clearance_mm, half_len = o.finger_length_mm / 2;
	int n = 0;
	for (const auto& p : pts)
	{
		const Eigen::Vector3d q = T_AinG * p;
		n += std::abs(q.x()) <= o.finger_width_mm / 2 + c &&
		     std::abs(q.y()) <= o.gripper_opening_max_mm / 2 + c && q.z() <= half_len + c &&
		     q.z() >= -half_len - o.approach_distance_mm - c;
	}
	return n;
}

std::string fmt(const char* text, double a, double b)
{
	std::ostringstream s;
	s << std::setprecision(5) << text << " (" << a << " mm vs " << b << " mm)";
	return s.str();
}
}  // namespace

namespace
{
using O = GraspFeasibilityOptions;

const util::OptionsBinder<O>& graspFeasibilityOptionsBinder()
{
	static const auto b = util::OptionsBinder<O>()
	    .number("gripper_opening_max_mm", &O::gripper_opening_max_mm, 0, 1e6)
	    .number("grip_margin_mm", &O::grip_margin_mm, 0, 1e6)
	    .number("finger_length_mm", &O::finger_length_mm, 0, 1e6)
	    .number("finger_width_mm", &O::finger_width_mm, 0, 1e6)
	    .number("approach_distance_mm", &O::approach_distance_mm, 0, 1e6)
	    .number("table_clearance_mm", &O::table_clearance_mm, 0, 1e6)
	    .number("neighbour_clearance_mm", &O::neighbour_clearance_mm, 0, 1e6)
	    .number("sample_step_mm", &O::sample_step_mm, 1e-3, 1e6);
	return b;
}
}  // namespace

void GraspFeasibilityOptions::loadFromConfigFile(const mrpt::config::CConfigFileBase& cfg,
                                                 const std::string& section)
{
	graspFeasibilityOptionsBinder().load(cfg, section, *this);
}

void GraspFeasibilityOptions::dump(std::ostream& out) const
{
	graspFeasibilityOptionsBinder().dump(out, *this);
}

std::vector<Eigen::Vector3d> sampleWireFrame(const model::WireFrame& wf, const Eigen::Isometry3d& T,
                                             double step_mm)
{
	std::vector<Eigen::Vector3d> out;
	for (const auto& l : wf.lines) sampleLine(l, T, step_mm, out);
	for (const auto& c : wf.conics) sampleConic(c, T, step_mm, out);
	return out;
}

GraspCheck checkGrasp(const Eigen::Isometry3d& T_GinA,
                      const std::vector<Eigen::Vector3d>& object_points_A,
                      const std::vector<Eigen::Vector3d>& neighbour_points_A, double table_z_mm,
                      const AnalyticIk& ik, const GraspFeasibilityOptions& o)
{
	GraspCheck c;
	const IkResult r = ik.solve(T_GinA);
	c.solutions = r.solutions;
	if (r.solutions.empty()) c.reasons.push_back("out of reach: " + r.reason());
	const Eigen::Isometry3d T_AinG = T_GinA.inverse(Eigen::Isometry);
	const auto [width, far] = widthBetweenFingers(T_AinG, object_points_A, o);
	c.width_mm = width;
	const double room = o.gripper_opening_max_mm / 2 - o.grip_margin_mm;
	if (width < 0)
		c.reasons.push_back("no object point between the fingers at the grasp");
	else if (far > room)
		c.reasons.push_back(
		    fmt("object too wide for the gripper: half-width from the grasp point "
		        "vs half-opening less margin",
		        far, room));
	c.table_clearance_mm = lowestFingertip(T_GinA, o) - table_z_mm;
	if (c.table_clearance_mm < o.table_clearance_mm)
		c.reasons.push_back(
		    fmt("fingertips too close to the table", c.table_clearance_mm, o.table_clearance_mm));
	c.neighbour_points_in_path = pointsInSweptBox(T_AinG, neighbour_points_A, o);
	if (c.neighbour_points_in_path > 0)
		c.reasons.push_back(std::to_string(c.neighbour_points_in_path) +
		                    " neighbouring-object points inside the gripper's approach path");
	return c;
}

}  // namespace mrolr::arm
