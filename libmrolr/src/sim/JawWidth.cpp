// The jaw distance of a gripper closed on an object's solid (sampled along the closing axis).
#include <mrolr/sim/JawWidth.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace mrolr::sim
{
namespace
{
constexpr double kSampleStep_mm = 0.5;  ///< resolution of the jaw distance along y_G

Eigen::Vector3d inPart(const world::ShapePart& part, const Eigen::Vector3d& p_inO)
{
	const double yaw = part.yaw_deg * M_PI / 180.0;
	return Eigen::AngleAxisd(-yaw, Eigen::Vector3d::UnitZ()) * (p_inO - part.base_mm);
}

bool insideBox(const world::ShapePart& part, const Eigen::Vector3d& q)
{
	const Eigen::Vector3d h = part.size_mm / 2;
	return std::abs(q.x()) <= h.x() && std::abs(q.y()) <= h.y() && q.z() >= 0 &&
	       q.z() <= part.size_mm.z();
}

bool insideFrustum(const world::ShapePart& part, const Eigen::Vector3d& q)
{
	if (q.z() < 0 || q.z() > part.height_mm) return false;
	const double f = part.height_mm > 0 ? q.z() / part.height_mm : 0;
	const double r = part.radius_bottom_mm + f * (part.radius_top_mm - part.radius_bottom_mm);
	return std::hypot(q.x(), q.y()) <= r;
}

/** The handle: a half ring in the plane of z and the part's x (yawed), outside the body. */
bool insideHandle(const world::ShapePart& part, const Eigen::Vector3d& q)
{
	if (std::abs(q.y()) > part.width_mm / 2 || q.x() < 0) return false;
	const double rho = std::hypot(q.x(), q.z());
	return std::abs(rho - part.radius_mm) <= part.thickness_mm / 2;
}

bool insidePart(const world::ShapePart& part, const Eigen::Vector3d& p_inO)
{
	const Eigen::Vector3d q = inPart(part, p_inO);
	switch (part.kind)
	{
		case world::ShapePart::Kind::Box: return insideBox(part, q);
		case world::ShapePart::Kind::Frustum: return insideFrustum(part, q);
		case world::ShapePart::Kind::Handle: return insideHandle(part, q);
	}
	return false;
}
}  // namespace

bool insideShape(const world::ObjectShape& shape, const Eigen::Vector3d& p_inO_mm)
{
	for (const auto& part : shape.parts)
		if (insidePart(part, p_inO_mm)) return true;
	return false;
}

double extentAlongYMm(const world::ObjectShape& shape, const Eigen::Isometry3d& T_GinO_mm,
                      const SlabSampling& s)
{
	double lo = std::numeric_limits<double>::infinity(), hi = -lo;
	const int ny = std::max(1, static_cast<int>(std::ceil(2 * s.half_y_mm / kSampleStep_mm)));
	for (int ix = 0; ix < s.nx; ++ix)
		for (int iz = 0; iz < s.nz; ++iz)
			for (int iy = 0; iy <= ny; ++iy)
			{
				const Eigen::Vector3d p_inG(
				    s.nx > 1 ? (2.0 * ix / (s.nx - 1) - 1) * s.half_x_mm : 0,
				    (2.0 * iy / ny - 1) * s.half_y_mm,
				    s.nz > 1 ? (2.0 * iz / (s.nz - 1) - 1) * s.half_z_mm : 0);
				if (!insideShape(shape, T_GinO_mm * p_inG)) continue;
				lo = std::min(lo, p_inG.y()), hi = std::max(hi, p_inG.y());
			}
	return hi >= lo ? hi - lo + kSampleStep_mm : 0.0;
}

double jawWidthMm(const world::ObjectShape& shape, const Eigen::Isometry3d& T_OinG_mm,
                  const JawGeometry& jaws)
{
	const SlabSampling s{jaws.finger_width_mm / 2, 5, jaws.opening_mm / 2, jaws.finger_length_mm / 2,
	                     9};
	return extentAlongYMm(shape, T_OinG_mm.inverse(Eigen::Isometry), s);
}

}  // namespace mrolr::sim
