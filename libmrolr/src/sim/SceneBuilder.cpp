#include <mrolr/geometry/Frames.h>
#include <mrolr/sim/ObjectVisual.h>
#include <mrolr/sim/Placement.h>
#include <mrolr/sim/SceneBuilder.h>
#include <mrolr/sim/Textures.h>

#include <mrpt/math/CMatrixFixed.h>
#include <mrpt/opengl/CBox.h>
#include <mrpt/opengl/CSphere.h>
#include <mrpt/opengl/CTexturedPlane.h>

#include <filesystem>
#include <tuple>

namespace mrolr::sim
{
namespace
{
using mrpt::opengl::CBox;

/** Pose (MRPT axes of W) of a plane whose local x, y, z are right, up, normal (thesis axes). */
mrpt::poses::CPose3D planePose(const Eigen::Vector3d& centre, const Eigen::Vector3d& up,
                               const Eigen::Vector3d& normal)
{
	Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
	T.linear().col(0) = up.cross(normal);
	T.linear().col(1) = up;
	T.linear().col(2) = normal;
	T.translation() = centre;
	return geometry::cameraPoseToMrpt(T);
}

void addPlane(mrpt::opengl::COpenGLScene& sc, const mrpt::img::CImage& tex,
              const Eigen::Vector3d& centre, const Eigen::Vector3d& up,
              const Eigen::Vector3d& normal, double w_m, double h_m, const std::string& name)
{
	auto p = mrpt::opengl::CTexturedPlane::Create(-w_m / 2, w_m / 2, -h_m / 2, h_m / 2);
	p->assignImage(tex);
	p->setPose(planePose(centre, up, normal));
	p->setName(name);
	sc.insert(p);
}

void addRoom(mrpt::opengl::COpenGLScene& sc, const world::World& w)
{
	const auto& r = w.room;
	const Eigen::Vector3d c = (r.min_m + r.max_m) / 2, s = r.max_m - r.min_m;
	const auto wall = loadTexture(r.wall_texture, w.directory());
	const Eigen::Vector3d X = Eigen::Vector3d::UnitX(), Y = Eigen::Vector3d::UnitY(),
	                      Z = Eigen::Vector3d::UnitZ();
	addPlane(sc, loadTexture(r.floor_texture, w.directory()), {c.x(), r.min_m.y(), c.z()}, Z, Y,
	         s.x(), s.z(), "floor");
	addPlane(sc, loadTexture(r.ceiling_texture, w.directory()), {c.x(), r.max_m.y(), c.z()}, Z, -Y,
	         s.x(), s.z(), "ceiling");
	addPlane(sc, wall, {r.min_m.x(), c.y(), c.z()}, Y, X, s.z(), s.y(), "wall_right");
	addPlane(sc, wall, {r.max_m.x(), c.y(), c.z()}, Y, -X, s.z(), s.y(), "wall_left");
	addPlane(sc, wall, {c.x(), c.y(), r.min_m.z()}, Y, Z, s.x(), s.y(), "wall_back");
	addPlane(sc, wall, {c.x(), c.y(), r.max_m.z()}, Y, -Z, s.x(), s.y(), "wall_front");
}

/** An upright box (thesis sizes: along own x, height, along own z) on the floor. */
CBox::Ptr floorBox(const world::World& w, double x, double z, double yaw_deg,
                   const Eigen::Vector3d& size, double bottom_y, const Eigen::Vector3d& colour)
{
	// MRPT axes: local x = own z (depth), local y = own x, local z = up
	auto b = CBox::Create(mrpt::math::TPoint3D(-size.z() / 2, -size.x() / 2, 0),
	                      mrpt::math::TPoint3D(size.z() / 2, size.x() / 2, size.y()));
	b->setPose(mrpt::poses::CPose3D(z, x, w.room.floorY() + bottom_y, yaw_deg * M_PI / 180, 0, 0));
	b->setColor(float(colour[0]), float(colour[1]), float(colour[2]));
	return b;
}

void addTable(mrpt::opengl::COpenGLScene& sc, const world::World& w, const world::Table& t)
{
	const double top = 0.03, leg = 0.05;
	auto topBox = floorBox(w, t.x_m, t.z_m, t.yaw_deg, {t.length_m, top, t.depth_m},
	                       t.top_height_m - top, t.top_colour);
	topBox->setName("table." + t.name);
	sc.insert(topBox);
	const Eigen::Matrix3d R = R_aboutVertical(t.yaw_deg * M_PI / 180);
	for (double sx : {-1.0, 1.0})
		for (double sz : {-1.0, 1.0})
		{
			const Eigen::Vector3d off =
			    R * Eigen::Vector3d(sx * (t.length_m / 2 - leg), 0, sz * (t.depth_m / 2 - leg));
			sc.insert(floorBox(w, t.x_m + off.x(), t.z_m + off.z(), t.yaw_deg,
			                   {leg, t.top_height_m - top, leg}, 0, {0.3, 0.3, 0.3}));
		}
}

/** A box whose four sides and top carry @p tex (thesis axes of W; sides face outwards). */
void addTexturedBox(mrpt::opengl::COpenGLScene& sc, const world::World& w, const world::Obstacle& o,
                    const mrpt::img::CImage& tex)
{
	const Eigen::Matrix3d R = R_aboutVertical(o.yaw_deg * M_PI / 180);
	const Eigen::Vector3d c(o.x_m, w.room.floorY() + o.size_m.y() / 2, o.z_m), s = o.size_m / 2;
	const Eigen::Vector3d Y = Eigen::Vector3d::UnitY();
	for (const auto& [axis, half, width] :
	     {std::tuple{Eigen::Vector3d(1, 0, 0), s.x(), o.size_m.z()},
	      {Eigen::Vector3d(-1, 0, 0), s.x(), o.size_m.z()},
	      {Eigen::Vector3d(0, 0, 1), s.z(), o.size_m.x()},
	      {Eigen::Vector3d(0, 0, -1), s.z(), o.size_m.x()}})
		addPlane(sc, tex, c + R * axis * half, Y, R * axis, width, o.size_m.y(),
		         "obstacle." + o.name);
	addPlane(sc, tex, c + Y * s.y(), R * Eigen::Vector3d::UnitZ(), Y, o.size_m.x(), o.size_m.z(),
	         "obstacle." + o.name);
}

void addObstacle(mrpt::opengl::COpenGLScene& sc, const world::World& w, const world::Obstacle& o)
{
	if (!o.texture.empty()) return addTexturedBox(sc, w, o, loadTexture(o.texture, w.directory()));
	auto box = floorBox(w, o.x_m, o.z_m, o.yaw_deg, o.size_m, 0, o.colour);
	box->setName("obstacle." + o.name);
	sc.insert(box);
}

void addPatches(mrpt::opengl::COpenGLScene& sc, const world::World& w)
{
	for (const auto& p : w.patches)
		addPlane(sc, loadTexture(p.texture, w.directory()), p.centre_m, p.up, p.normal, p.width_m,
		         p.height_m, "patch." + p.name);
}

void addObjects(LabScene& lab, const world::World& w)
{
	for (const auto& o : w.objects)
	{
		auto v = objectVisual(lab.shapes.at(o.model));
		v->setPose(objectPoseMrpt(w, o));
		v->setName("object." + o.name);
		lab.scene->insert(v);
	}
}

void addPointLandmarks(mrpt::opengl::COpenGLScene& sc, const world::World& w)
{
	for (const auto& l : w.landmarks)
	{
		auto s = mrpt::opengl::CSphere::Create(0.03f);
		s->setLocation(geometry::pointToMrpt(l.p_LinW));
		s->setColor(1, 1, l.known ? 0.2f : 1.0f);
		sc.insert(s);
	}
}
}  // namespace

std::map<std::string, world::ObjectShape> loadObjectShapes(const world::World& w)
{
	std::map<std::string, world::ObjectShape> out;
	for (const auto& o : w.objects)
	{
		if (out.count(o.model)) continue;
		const auto path = std::filesystem::path(w.objects_dir) / (o.model + ".ini");
		try
		{
			out.emplace(o.model, world::ObjectShape::load(path.string()));
		}
		catch (const world::WorldError& e)
		{
			throw world::WorldError(w.path + " [object." + o.name + "] model = '" + o.model +
			                        "': " + e.what());
		}
	}
	return out;
}

LabScene buildLabScene(const world::World& w, bool draw_point_landmarks)
{
	return buildLabScene(w, loadObjectShapes(w), draw_point_landmarks);
}

LabScene buildLabScene(const world::World& w,
                       const std::map<std::string, world::ObjectShape>& shapes,
                       bool draw_point_landmarks)
{
	LabScene lab;
	lab.scene = mrpt::opengl::COpenGLScene::Create();
	lab.shapes = shapes;
	if (w.has_room) addRoom(*lab.scene, w);
	for (const auto& t : w.tables) addTable(*lab.scene, w, t);
	for (const auto& o : w.obstacles) addObstacle(*lab.scene, w, o);
	addPatches(*lab.scene, w);
	addObjects(lab, w);
	if (draw_point_landmarks) addPointLandmarks(*lab.scene, w);
	return lab;
}

}  // namespace mrolr::sim
