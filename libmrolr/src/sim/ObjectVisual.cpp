#include <mrolr/sim/ObjectVisual.h>
#include <mrolr/sim/ObjectWireFrame.h>
#include <mrolr/world/StrokeFont.h>

#include <mrpt/math/CMatrixFixed.h>
#include <mrpt/opengl/CBox.h>
#include <mrpt/opengl/CCylinder.h>
#include <mrpt/poses/CPose3D.h>

#include <cmath>

namespace mrolr::sim
{
namespace
{
constexpr double kMm = 1e-3;

mrpt::poses::CPose3D poseOf(const Eigen::Matrix3d& R, const Eigen::Vector3d& t_m)
{
	mrpt::math::CMatrixDouble44 H = mrpt::math::CMatrixDouble44::Identity();
	for (int i = 0; i < 3; ++i)
	{
		for (int j = 0; j < 3; ++j) H(i, j) = R(i, j);
		H(i, 3) = t_m[i];
	}
	return mrpt::poses::CPose3D(H);
}

void colourOf(mrpt::opengl::CRenderizable& r, const Eigen::Vector3d& c)
{
	r.setColor(float(c[0]), float(c[1]), float(c[2]));
}

/** A box of size s (m) centred at its local origin, posed by R, t. */
mrpt::opengl::CBox::Ptr centredBox(const Eigen::Vector3d& s, const Eigen::Matrix3d& R,
                                   const Eigen::Vector3d& t_m, const Eigen::Vector3d& colour)
{
	auto b = mrpt::opengl::CBox::Create(mrpt::math::TPoint3D(-s.x() / 2, -s.y() / 2, -s.z() / 2),
	                                    mrpt::math::TPoint3D(s.x() / 2, s.y() / 2, s.z() / 2));
	b->setPose(poseOf(R, t_m));
	colourOf(*b, colour);
	return b;
}

void addBox(mrpt::opengl::CSetOfObjects& out, const world::ShapePart& p)
{
	const Eigen::Vector3d centre = p.base_mm + Eigen::Vector3d(0, 0, p.size_mm.z() / 2);
	out.insert(centredBox(p.size_mm * kMm, R_aboutZ(p.yaw_deg), centre * kMm, p.colour));
}

void addFrustum(mrpt::opengl::CSetOfObjects& out, const world::ShapePart& p)
{
	auto c =
	    mrpt::opengl::CCylinder::Create(float(p.radius_bottom_mm * kMm),
	                                    float(p.radius_top_mm * kMm), float(p.height_mm * kMm), 64);
	c->setHasBases(true, true);
	c->setPose(poseOf(R_aboutZ(p.yaw_deg), p.base_mm * kMm));
	colourOf(*c, p.colour);
	out.insert(c);
}

void addHandle(mrpt::opengl::CSetOfObjects& out, const world::ShapePart& p)
{
	const Eigen::Matrix3d R = R_aboutZ(p.yaw_deg);
	const int n = 24;
	const double dt = M_PI / n, seg = p.radius_mm * dt * 1.08;
	for (int i = 0; i < n; ++i)
	{
		const double t = -M_PI / 2 + (i + 0.5) * dt;
		// local frame of the segment: x radial, z tangent, y across the ring
		const Eigen::Matrix3d Rt =
		    Eigen::AngleAxisd(-t, Eigen::Vector3d::UnitY()).toRotationMatrix();
		const Eigen::Vector3d c = p.base_mm + R * Eigen::Vector3d(p.radius_mm * std::cos(t), 0,
		                                                          p.radius_mm * std::sin(t));
		const Eigen::Vector3d size(p.thickness_mm, p.width_mm, seg);
		out.insert(centredBox(size * kMm, R * Rt, c * kMm, p.colour));
	}
}

void addMarking(mrpt::opengl::CSetOfObjects& out, const world::ObjectShape& o,
                const world::Marking& m)
{
	const BoxFace f = boxFace(*o.findPart(m.part), m.face);
	const double relief_mm = 0.8;
	for (const auto& s : world::strokeLetter(m.letter))
	{
		auto at = [&](const Eigen::Vector2d& q)
		{ return f.centre_mm + m.height_mm * ((q.x() - 0.3) * f.right + (q.y() - 0.5) * f.up); };
		const Eigen::Vector3d a = at(s.first), b = at(s.second);
		Eigen::Matrix3d R;
		R.col(0) = (b - a).normalized();
		R.col(2) = f.normal;
		R.col(1) = R.col(2).cross(R.col(0));
		const Eigen::Vector3d size((b - a).norm() + m.stroke_mm, m.stroke_mm, 2 * relief_mm);
		out.insert(centredBox(size * kMm, R, (a + b) / 2 * kMm, m.colour));
	}
}
}  // namespace

mrpt::opengl::CSetOfObjects::Ptr objectVisual(const world::ObjectShape& shape)
{
	auto set = mrpt::opengl::CSetOfObjects::Create();
	set->setName(shape.name);
	for (const auto& p : shape.parts)
	{
		if (p.kind == world::ShapePart::Kind::Box)
			addBox(*set, p);
		else if (p.kind == world::ShapePart::Kind::Frustum)
			addFrustum(*set, p);
		else
			addHandle(*set, p);
	}
	for (const auto& m : shape.markings) addMarking(*set, shape, m);
	return set;
}

}  // namespace mrolr::sim
