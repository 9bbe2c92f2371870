#include "WorldSections.h"

#include <mrolr/util/IniFields.h>

#include <cmath>

namespace mrolr::world::detail
{
namespace
{
Eigen::Vector3d vec3(const std::vector<double>& v)
{
	return {v[0], v[1], v[2]};
}

Eigen::Vector3d unitVector(const IniDocument& doc, const IniSection& s, const std::string& key)
{
	const Eigen::Vector3d v = vec3(requireNumbers(doc, s, key, 3));
	if (v.norm() < 1e-9) doc.fail(s, require(doc, s, key), "must not be the zero vector");
	return v.normalized();
}

Eigen::Vector3d colour(const IniDocument& doc, const IniSection& s, const std::string& key,
                       const Eigen::Vector3d& def)
{
	const Eigen::Vector3d c = vec3(optionalNumbers(doc, s, key, {def[0], def[1], def[2]}));
	if (c.minCoeff() < 0 || c.maxCoeff() > 1)
		doc.fail(s, *s.find(key), "colour components must be in [0, 1]");
	return c;
}

void requirePositive(const IniDocument& doc, const IniSection& s, const std::string& key,
                     const std::vector<double>& v)
{
	for (double x : v)
		if (x <= 0) doc.fail(s, require(doc, s, key), "sizes must be positive");
}
}  // namespace

Room parseRoom(const IniDocument& doc, const IniSection& s)
{
	rejectUnknownKeys(
	    doc, s,
	    {"min_m", "max_m", "wall_texture", "floor_texture", "ceiling_texture", "objects_dir"});
	Room r;
	r.min_m = vec3(requireNumbers(doc, s, "min_m", 3));
	r.max_m = vec3(requireNumbers(doc, s, "max_m", 3));
	if ((r.max_m - r.min_m).minCoeff() <= 0)
		doc.fail(s, require(doc, s, "max_m"), "max_m must exceed min_m in x, y and z");
	r.wall_texture = optionalString(s, "wall_texture", r.wall_texture);
	r.floor_texture = optionalString(s, "floor_texture", r.floor_texture);
	r.ceiling_texture = optionalString(s, "ceiling_texture", r.ceiling_texture);
	return r;
}

Patch parsePatch(const IniDocument& doc, const IniSection& s, const std::string& name)
{
	rejectUnknownKeys(doc, s, {"centre_m", "normal", "up", "size_m", "texture", "known"});
	Patch p;
	p.name = name;
	p.centre_m = vec3(requireNumbers(doc, s, "centre_m", 3));
	p.normal = unitVector(doc, s, "normal");
	p.up = unitVector(doc, s, "up");
	if (std::abs(p.normal.dot(p.up)) > 1e-3)
		doc.fail(s, require(doc, s, "up"), "'up' must be perpendicular to 'normal'");
	const auto size = requireNumbers(doc, s, "size_m", 2);
	requirePositive(doc, s, "size_m", size);
	p.width_m = size[0];
	p.height_m = size[1];
	p.texture = require(doc, s, "texture").value;
	p.known = optionalBool(doc, s, "known", false);
	return p;
}

namespace
{
/** The keys shared by tables and obstacles: centre_m = x z, yaw_deg, size_m (3 positive sizes). */
struct Footprint
{
	double x_m, z_m, yaw_deg;
	Eigen::Vector3d size;
};

Footprint readFootprint(const IniDocument& doc, const IniSection& s)
{
	const auto c = requireNumbers(doc, s, "centre_m", 2);
	const auto size = requireNumbers(doc, s, "size_m", 3);
	requirePositive(doc, s, "size_m", size);
	return {c[0], c[1], optionalNumbers(doc, s, "yaw_deg", {0.0})[0], vec3(size)};
}
}  // namespace

Table parseTable(const IniDocument& doc, const IniSection& s, const std::string& name)
{
	rejectUnknownKeys(doc, s, {"centre_m", "yaw_deg", "size_m", "top_colour"});
	const Footprint f = readFootprint(doc, s);
	Table t;
	t.name = name;
	t.x_m = f.x_m, t.z_m = f.z_m, t.yaw_deg = f.yaw_deg;
	t.length_m = f.size[0], t.depth_m = f.size[1], t.top_height_m = f.size[2];
	t.top_colour = colour(doc, s, "top_colour", t.top_colour);
	return t;
}

Obstacle parseObstacle(const IniDocument& doc, const IniSection& s, const std::string& name)
{
	rejectUnknownKeys(doc, s, {"centre_m", "yaw_deg", "size_m", "colour", "texture"});
	const Footprint f = readFootprint(doc, s);
	Obstacle o;
	o.name = name;
	o.x_m = f.x_m, o.z_m = f.z_m, o.yaw_deg = f.yaw_deg;
	o.size_m = f.size;
	o.colour = colour(doc, s, "colour", o.colour);
	o.texture = optionalString(s, "texture", "");
	return o;
}

PlacedObject parseObject(const IniDocument& doc, const IniSection& s, const std::string& name)
{
	rejectUnknownKeys(doc, s, {"model", "table", "position_m", "yaw_deg"});
	PlacedObject o;
	o.name = name;
	o.model = require(doc, s, "model").value;
	o.table = require(doc, s, "table").value;
	const auto p = requireNumbers(doc, s, "position_m", 2);
	o.x_m = p[0];
	o.z_m = p[1];
	o.yaw_deg = optionalNumbers(doc, s, "yaw_deg", {0.0})[0];
	return o;
}

MissionSpec parseMission(const IniDocument& doc, const IniSection& s)
{
	rejectUnknownKeys(doc, s, {"target", "table_waypoint", "home_waypoint"});
	return MissionSpec{require(doc, s, "target").value, require(doc, s, "table_waypoint").value,
	                   require(doc, s, "home_waypoint").value};
}

}  // namespace mrolr::world::detail
