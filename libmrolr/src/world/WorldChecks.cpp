#include "WorldSections.h"

#include <mrolr/util/IniFields.h>

#include <cmath>

namespace mrolr::world::detail
{
namespace
{
/** (x, z) of a W point in the table's own axes, relative to its centre. */
Eigen::Vector2d inTableAxes(const Table& t, double x_m, double z_m)
{
	const double a = t.yaw_deg * M_PI / 180.0;
	const double dx = x_m - t.x_m, dz = z_m - t.z_m;
	// the table's x axis is W's x turned by yaw about y; its z axis is W's z turned likewise
	return {std::cos(a) * dx - std::sin(a) * dz, std::sin(a) * dx + std::cos(a) * dz};
}

void checkObject(const IniDocument& doc, const World& w, const PlacedObject& o)
{
	const IniSection& s = *doc.find("object." + o.name);
	const Table* t = w.findTable(o.table);
	if (!t) doc.fail(s, *s.find("table"), "no section [table." + o.table + "]");
	const Eigen::Vector2d q = inTableAxes(*t, o.x_m, o.z_m);
	if (std::abs(q.x()) > t->length_m / 2 || std::abs(q.y()) > t->depth_m / 2)
		doc.fail(s, *s.find("position_m"), "not on the top of table '" + o.table + "'");
}

void checkMission(const IniDocument& doc, const World& w)
{
	const IniSection* s = doc.find("mission");
	if (!s) return;
	if (!w.findObject(w.mission.target))
		doc.fail(*s, *s->find("target"), "no section [object." + w.mission.target + "]");
	for (const char* key : {"table_waypoint", "home_waypoint"})
		if (!w.findWaypoint(s->find(key)->value))
			doc.fail(*s, *s->find(key), "no such waypoint in [waypoints]");
}
}  // namespace

void checkUniqueLandmarks(const IniDocument& doc, const World& w)
{
	for (size_t i = 0; i < w.landmarks.size(); ++i)
		for (size_t j = 0; j < i; ++j)
			if (w.landmarks[i].name == w.landmarks[j].name)
				throw WorldError(doc.path + ": landmark '" + w.landmarks[i].name +
				                 "' is defined twice (a [patch.NAME] is also a landmark NAME)");
}

void checkReferences(const IniDocument& doc, const World& w)
{
	checkUniqueLandmarks(doc, w);
	for (const auto& o : w.objects) checkObject(doc, w, o);
	checkMission(doc, w);
}

}  // namespace mrolr::world::detail
