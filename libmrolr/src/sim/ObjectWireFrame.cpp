#include <mrolr/sim/ObjectWireFrame.h>
#include <mrolr/world/StrokeFont.h>

#include <array>
#include <cmath>
#include <stdexcept>

namespace mrolr::sim
{
using world::ShapePart;

Eigen::Matrix3d R_aboutZ(double yaw_deg)
{
	return Eigen::AngleAxisd(yaw_deg * M_PI / 180.0, Eigen::Vector3d::UnitZ()).toRotationMatrix();
}

namespace
{
void addLine(model::WireFrame& wf, const Eigen::Vector3d& a, const Eigen::Vector3d& b)
{
	model::Line3 l;
	l.p1 = a;
	l.p2 = b;
	wf.lines.push_back(l);
}

bool sameCircle(const model::Conic3& a, const model::Conic3& b)
{
	return (a.centre - b.centre).norm() < 1e-9 && std::abs(a.a - b.a) < 1e-9 &&
	       std::abs(std::abs(a.normal.dot(b.normal)) - 1) < 1e-12 &&
	       std::abs(a.t2 - a.t1 - 2 * M_PI) < 1e-12 && std::abs(b.t2 - b.t1 - 2 * M_PI) < 1e-12;
}

void addConic(model::WireFrame& wf, const model::Conic3& c)
{
	for (const auto& k : wf.conics)
		if (sameCircle(k, c)) return;
	wf.conics.push_back(c);
}

model::Conic3 arc(const Eigen::Vector3d& centre, const Eigen::Vector3d& normal,
                  const Eigen::Vector3d& major, double r, double t1, double t2)
{
	model::Conic3 c;
	c.centre = centre;
	c.normal = normal;
	c.major = major;
	c.a = c.b = r;
	c.t1 = t1;
	c.t2 = t2;
	return c;
}

void addBox(model::WireFrame& wf, const ShapePart& p)
{
	const Eigen::Matrix3d R = R_aboutZ(p.yaw_deg);
	std::array<Eigen::Vector3d, 8> c;
	for (int i = 0; i < 8; ++i)
	{
		const Eigen::Vector3d s((i & 1) ? 0.5 : -0.5, (i & 2) ? 0.5 : -0.5, (i & 4) ? 1.0 : 0.0);
		c[i] = p.base_mm + R * s.cwiseProduct(p.size_mm);
	}
	for (int i = 0; i < 8; ++i)
		for (int bit : {1, 2, 4})
			if (!(i & bit)) addLine(wf, c[i], c[i | bit]);
}

void addFrustum(model::WireFrame& wf, const ShapePart& p)
{
	const Eigen::Vector3d z = Eigen::Vector3d::UnitZ();
	const Eigen::Vector3d x = R_aboutZ(p.yaw_deg) * Eigen::Vector3d::UnitX();
	if (p.radius_bottom_mm > 0) addConic(wf, arc(p.base_mm, z, x, p.radius_bottom_mm, 0, 2 * M_PI));
	if (p.radius_top_mm > 0)
		addConic(wf, arc(p.base_mm + p.height_mm * z, z, x, p.radius_top_mm, 0, 2 * M_PI));
}

void addHandle(model::WireFrame& wf, const ShapePart& p)
{
	// the half ring lies in the plane of the outward direction d and z; normal = −side so that
	// normal × d = z and t ∈ [−π/2, π/2] sweeps from below, outwards, to above
	const Eigen::Vector3d d = R_aboutZ(p.yaw_deg) * Eigen::Vector3d::UnitX();
	const Eigen::Vector3d side = R_aboutZ(p.yaw_deg) * Eigen::Vector3d::UnitY();
	for (double s : {-0.5, 0.5})
		for (double r : {p.radius_mm - p.thickness_mm / 2, p.radius_mm + p.thickness_mm / 2})
			addConic(wf, arc(p.base_mm + s * p.width_mm * side, -side, d, r, -M_PI / 2, M_PI / 2));
}

void addMarking(model::WireFrame& wf, const world::ObjectShape& o, const world::Marking& m)
{
	const BoxFace f = boxFace(*o.findPart(m.part), m.face);
	auto at = [&](const Eigen::Vector2d& q)
	{ return f.centre_mm + m.height_mm * ((q.x() - 0.3) * f.right + (q.y() - 0.5) * f.up); };
	for (const auto& s : world::strokeLetter(m.letter)) addLine(wf, at(s.first), at(s.second));
}
}  // namespace

BoxFace boxFace(const ShapePart& p, const std::string& face)
{
	const Eigen::Matrix3d R = R_aboutZ(p.yaw_deg);
	const Eigen::Vector3d h = p.size_mm / 2;
	BoxFace f;
	f.up = R * Eigen::Vector3d::UnitZ();
	if (face == "+x")
		f.normal = R * Eigen::Vector3d::UnitX();
	else if (face == "-x")
		f.normal = -(R * Eigen::Vector3d::UnitX());
	else if (face == "+y")
		f.normal = R * Eigen::Vector3d::UnitY();
	else if (face == "-y")
		f.normal = -(R * Eigen::Vector3d::UnitY());
	else if (face == "+z")
	{
		f.normal = R * Eigen::Vector3d::UnitZ();
		f.up = R * Eigen::Vector3d::UnitX();
	}
	else
		throw std::invalid_argument("unknown box face '" + face + "'");
	const Eigen::Vector3d local = R.transpose() * f.normal;
	f.centre_mm = p.base_mm + Eigen::Vector3d(0, 0, h.z()) + R * local.cwiseProduct(h);
	f.right = f.up.cross(f.normal);
	return f;
}

model::WireFrame objectWireFrame(const world::ObjectShape& shape)
{
	model::WireFrame wf;
	wf.name = shape.name;
	wf.frame = model::WireFrameFrame::Object;
	for (const auto& p : shape.parts)
	{
		if (p.kind == ShapePart::Kind::Box)
			addBox(wf, p);
		else if (p.kind == ShapePart::Kind::Frustum)
			addFrustum(wf, p);
		else
			addHandle(wf, p);
	}
	for (const auto& m : shape.markings) addMarking(wf, shape, m);
	int id = 1;
	for (auto& l : wf.lines) l.id = id++;
	for (auto& c : wf.conics) c.id = id++;
	wf.has_grasp = shape.has_grasp;
	wf.grasp.p_mm = shape.grasp_p_mm;
	wf.grasp.yaw_deg = shape.grasp_yaw_deg;
	wf.grasp.pitch_deg = shape.grasp_pitch_deg;
	wf.grasp.roll_deg = shape.grasp_roll_deg;
	return wf;
}

}  // namespace mrolr::sim
