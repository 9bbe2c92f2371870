#include "WorldSections.h"

#include <mrolr/util/IniFields.h>
#include <mrolr/world/World.h>

#include <cmath>
#include <filesystem>

namespace mrolr::world
{
namespace
{
Landmark parseLandmark(const IniDocument& doc, const IniSection& s, const IniEntry& e)
{
	auto f = fieldsOf(e);
	Landmark l;
	l.name = e.key;
	if (f.size() == 4)
	{
		if (f[3] != "known") doc.fail(s, e, "fourth field '" + f[3] + "' must be 'known'");
		l.known = true;
		f.pop_back();
	}
	if (f.size() != 3) doc.fail(s, e, "expected 'X Y Z [known]' (metres, W frame)");
	for (int i = 0; i < 3; ++i) l.p_LinW[i] = numberField(doc, s, e, f[i]);
	return l;
}

Waypoint parseWaypoint(const IniDocument& doc, const IniSection& s, const IniEntry& e)
{
	if (fieldsOf(e).size() != 3) doc.fail(s, e, "expected 'z x phi_deg'");
	const auto v = numbers(doc, s, e, 3);
	return Waypoint{e.key, v[0], v[1], v[2] * M_PI / 180.0};
}

/** "kind.NAME" → (kind, NAME); kind is empty for a plain section name. */
std::pair<std::string, std::string> splitSectionName(const std::string& section)
{
	const auto dot = section.find('.');
	if (dot == std::string::npos) return {"", section};
	return {section.substr(0, dot), section.substr(dot + 1)};
}

void addPatch(World& w, const Patch& p)
{
	w.patches.push_back(p);
	w.landmarks.push_back(Landmark{p.name, p.centre_m, p.known});
}

void parseNamedSection(const IniDocument& doc, const IniSection& s, World& w)
{
	const auto [kind, name] = splitSectionName(s.name);
	if (name.empty())
		throw WorldError(doc.path + ":" + std::to_string(s.line) + " [" + s.name + "]: empty name");
	if (kind == "patch")
		addPatch(w, detail::parsePatch(doc, s, name));
	else if (kind == "table")
		w.tables.push_back(detail::parseTable(doc, s, name));
	else if (kind == "obstacle")
		w.obstacles.push_back(detail::parseObstacle(doc, s, name));
	else if (kind == "object")
		w.objects.push_back(detail::parseObject(doc, s, name));
	else
		throw WorldError(
		    doc.path + ":" + std::to_string(s.line) + " [" + s.name +
		    "]: unknown section (expected landmarks, waypoints, room, mission, patch.NAME, "
		    "table.NAME, obstacle.NAME or object.NAME)");
}

void parseRoomSection(const IniDocument& doc, const IniSection& s, World& w)
{
	w.has_room = true;
	w.room = detail::parseRoom(doc, s);
	const std::string dir = optionalString(s, "objects_dir", "../../datasets/objects");
	w.objects_dir = (std::filesystem::path(w.directory()) / dir).lexically_normal().string();
}

void parseSection(const IniDocument& doc, const IniSection& s, World& w)
{
	if (s.name == "landmarks")
		for (const auto& e : s.entries) w.landmarks.push_back(parseLandmark(doc, s, e));
	else if (s.name == "waypoints")
		for (const auto& e : s.entries) w.waypoints.push_back(parseWaypoint(doc, s, e));
	else if (s.name == "room")
		parseRoomSection(doc, s, w);
	else if (s.name == "mission")
		w.mission = detail::parseMission(doc, s);
	else
		parseNamedSection(doc, s, w);
}
}  // namespace

World World::fromDocument(const IniDocument& doc)
{
	World w;
	w.path = doc.path;
	w.objects_dir = (std::filesystem::path(w.directory()) / "../../datasets/objects")
	                    .lexically_normal()
	                    .string();
	for (const auto& s : doc.sections) parseSection(doc, s, w);
	detail::checkReferences(doc, w);
	return w;
}

World World::load(const std::string& path)
{
	return fromDocument(IniDocument::load(path));
}

World World::parse(const std::string& text, const std::string& path)
{
	return fromDocument(IniDocument::parse(text, path));
}

std::string World::directory() const
{
	const auto dir = std::filesystem::path(path).parent_path();
	return dir.empty() ? std::string(".") : dir.string();
}

const Table* World::findTable(const std::string& name) const
{
	for (const auto& t : tables)
		if (t.name == name) return &t;
	return nullptr;
}

const PlacedObject* World::findObject(const std::string& name) const
{
	for (const auto& o : objects)
		if (o.name == name) return &o;
	return nullptr;
}

const Landmark* World::findLandmark(const std::string& name) const
{
	for (const auto& l : landmarks)
		if (l.name == name) return &l;
	return nullptr;
}

const Waypoint* World::findWaypoint(const std::string& name) const
{
	for (const auto& w : waypoints)
		if (w.name == name) return &w;
	return nullptr;
}

}  // namespace mrolr::world
