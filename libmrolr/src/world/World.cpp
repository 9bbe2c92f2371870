#include <mrolr/world/Fields.h>
#include <mrolr/world/World.h>

#include <cmath>

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
}  // namespace

World World::fromDocument(const IniDocument& doc)
{
	World w;
	w.path = doc.path;
	if (const IniSection* s = doc.find("landmarks"))
		for (const auto& e : s->entries) w.landmarks.push_back(parseLandmark(doc, *s, e));
	if (const IniSection* s = doc.find("waypoints"))
		for (const auto& e : s->entries) w.waypoints.push_back(parseWaypoint(doc, *s, e));
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
