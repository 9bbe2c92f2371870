#include <mrolr/arm/GraspFeasibility.h>
#include <mrolr/arm/TopGrasp.h>

#include <mrpt/core/bits_math.h>

#include <cmath>
#include <limits>
#include <stdexcept>

namespace mrolr::arm
{
namespace
{
/** Extent of the points along the horizontal direction (sin yaw, −cos yaw, 0) = y_G of a top grasp.
 */
double extentAcross(const std::vector<Eigen::Vector3d>& pts, double yaw_rad)
{
	const Eigen::Vector3d axis(std::sin(yaw_rad), -std::cos(yaw_rad), 0);
	double lo = std::numeric_limits<double>::infinity(), hi = -lo;
	for (const auto& p : pts)
	{
		lo = std::min(lo, p.dot(axis));
		hi = std::max(hi, p.dot(axis));
	}
	return hi - lo;
}
}  // namespace

Eigen::Vector3d segmentCentroid(const std::vector<model::Line3>& lines,
                                const std::vector<model::Conic3>& conics)
{
	const size_t n = lines.size() + conics.size();
	if (n == 0) throw std::invalid_argument("segmentCentroid: no matched segments");
	Eigen::Vector3d sum = Eigen::Vector3d::Zero();
	for (const auto& l : lines) sum += 0.5 * (l.p1 + l.p2);
	for (const auto& c : conics) sum += c.centre;
	return sum / static_cast<double>(n);
}

GripperPose topGrasp(const std::vector<model::Line3>& lines,
                     const std::vector<model::Conic3>& conics)
{
	GripperPose g;
	g.p_mm = segmentCentroid(lines, conics);
	g.pitch_deg = 90;
	model::WireFrame wf;
	wf.lines = lines;
	wf.conics = conics;
	const auto pts = sampleWireFrame(wf, Eigen::Isometry3d::Identity(), 2.0);
	double best = std::numeric_limits<double>::infinity();
	for (int yaw = 0; yaw < 180; ++yaw)
	{
		const double w = extentAcross(pts, mrpt::DEG2RAD(static_cast<double>(yaw)));
		if (w < best - 1e-9) best = w, g.yaw_deg = yaw;
	}
	return g;
}

}  // namespace mrolr::arm
