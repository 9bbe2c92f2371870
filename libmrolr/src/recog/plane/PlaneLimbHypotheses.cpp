// Limb hypotheses on the support plane (PlaneHypotheses.h): a scene line along the plane's normal
// taken as the outline of one of the model's cylinders.
#include <mrolr/recog/images/Limbs.h>
#include <mrolr/recog/plane/PlaneHypotheses.h>

#include "../UprightPose.h"

#include <algorithm>
#include <cmath>

namespace mrolr::recog
{
namespace
{
constexpr double kDeg = M_PI / 180;
using detail::standOn;
using detail::uprightRotation;
}  // namespace

void PlaneHypothesisGenerator::findLimbCylinders()
{
	const double axis_cos = std::cos(opts_.rim_normal_tol_deg * kDeg);
	for (const RevolutionBody& b : revolutionBodiesOf(model_))
	{
		if (std::abs(b.axis_dir.z()) < axis_cos) continue;
		for (const ProfileSegment& f : b.profile)
		{
			if (std::abs(f.r0_mm - f.r1_mm) > opts_.limb_max_taper_mm ||
			    f.z1_mm - f.z0_mm < opts_.limb_min_mm)
				continue;
			const Eigen::Vector3d p0 = b.axis_point + f.z0_mm * b.axis_dir;
			const Eigen::Vector3d p1 = b.axis_point + f.z1_mm * b.axis_dir;
			LimbCylinder c;
			c.axis_x_mm = 0.5 * (p0.x() + p1.x());
			c.axis_y_mm = 0.5 * (p0.y() + p1.y());
			c.r_mm = 0.5 * (f.r0_mm + f.r1_mm);
			c.z_lo_mm = std::min(p0.z(), p1.z());
			c.z_hi_mm = std::max(p0.z(), p1.z());
			cylinders_.push_back(c);
		}
	}
}

void PlaneHypothesisGenerator::addLimbHypotheses(const LimbCylinder& c, size_t s,
                                                 const Feature& sl, const SupportPlane& plane,
                                                 std::vector<PlaneHypothesis>& out) const
{
	const Eigen::Vector3d& n = plane.n_S;
	// the plane through the camera centre (origin of S) and the line is tangent to the cylinder
	const Eigen::Vector3d across = n.cross(sl.m);
	if (across.norm() < 1e-9) return;  // looking straight down the line
	const Eigen::Vector3d u = across.normalized();
	const Eigen::Vector3d axis_O(c.axis_x_mm, c.axis_y_mm, base_z_mm_);
	const double step = std::max(1.0, opts_.rim_yaw_step_deg) * kDeg;
	for (const double side : {1.0, -1.0})
	{
		const Eigen::Vector3d a_S = sl.m + side * c.r_mm * u;  // a point of the axis
		for (double yaw = 0; yaw < 2 * M_PI - 1e-9; yaw += step)
		{
			PlaneHypothesis h;
			h.T_OinS.linear() = uprightRotation(n, yaw);
			h.T_OinS.translation() =
			    standOn(a_S - h.T_OinS.linear() * axis_O, plane, base_z_mm_);
			h.from_limb = true;
			h.model_feature = -1;
			h.scene_feature = static_cast<int>(s);
			out.push_back(h);
		}
	}
}

}  // namespace mrolr::recog
