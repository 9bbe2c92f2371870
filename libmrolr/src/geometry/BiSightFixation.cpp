// Symmetric fixation of a known point (thesis 4.2.4, eqs 4.25–4.33) and the joint limits.
#include <mrolr/geometry/BiSightHead.h>

#include <cmath>
#include <sstream>

namespace mrolr::geometry
{
namespace
{
constexpr double kRadToDeg = 180.0 / M_PI;

[[noreturn]] void failFor(const Eigen::Vector3d& p, const char* reason)
{
	std::ostringstream s;
	s << "point (" << p.x() << ", " << p.y() << ", " << p.z() << ") m in C0 " << reason;
	throw FixationError(s.str());
}

void checkJoint(const char* name, double angle_rad, double limit_deg)
{
	if (std::abs(angle_rad) * kRadToDeg <= limit_deg) return;
	std::ostringstream s;
	s << name << " " << angle_rad * kRadToDeg << " deg is beyond the joint limit ±" << limit_deg
	  << " deg";
	throw FixationError(s.str());
}
}  // namespace

void BiSightHead::checkJointLimits(const HeadAngles& a) const
{
	checkJoint("pan", a.pan, options_.pan_limit_deg);
	checkJoint("tilt", a.tilt, options_.tilt_limit_deg);
	checkJoint("left vergence", a.verg_left, options_.vergence_limit_deg);
	checkJoint("right vergence", a.verg_right, options_.vergence_limit_deg);
}

HeadAngles BiSightHead::fixate(const Eigen::Vector3d& m) const
{
	if (std::hypot(m.x(), m.z()) < 1e-9)
		failFor(m, "lies on the pan axis, where the pan angle is undefined");
	HeadAngles a;
	a.pan = std::atan2(m.x(), m.z());  // eq 4.27: m_C1,x = 0
	const Eigen::Vector3d m1 = R_C1fromC0(a.pan) * m;
	// eq 4.30: m_C2,y = cos e·y − sin e·(z − p) − c = r sin(φ − e) − c = 0.
	const double y = m1.y(), zr = m1.z() - options_.pan_offset_m;
	const double r = std::hypot(y, zr), c = options_.tilt_offset_m;
	if (r <= std::abs(c)) failFor(m, "is closer to the tilt axis than the tilt offset c");
	a.tilt = std::atan2(y, zr) - std::asin(c / r);
	// After the tilt m_C2 = (∓I/2, 0, z2) with z2 = r cos(φ − e) > 0; eq 4.32: m_L,x = 0.
	const double z2 = std::sqrt(r * r - c * c), half_I = options_.interocular_m / 2;
	if (std::hypot(half_I, z2) <= options_.optic_offset_m)
		failFor(m, "is behind the optic centres (closer than the offset n)");
	a.verg_left = std::atan2(-half_I, z2);
	a.verg_right = -a.verg_left;  // eq 4.33
	if (m.z() < 0 && std::abs(a.pan) * kRadToDeg > options_.pan_limit_deg)
		failFor(m, "is behind the head, beyond the pan limit");
	checkJointLimits(a);
	return a;
}

}  // namespace mrolr::geometry
