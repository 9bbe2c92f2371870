#pragma once
// Parsers of the scenery sections of a world file (private to the world area).

#include <mrolr/world/World.h>

namespace mrolr::world::detail
{
Room parseRoom(const IniDocument& doc, const IniSection& s);
Patch parsePatch(const IniDocument& doc, const IniSection& s, const std::string& name);
Table parseTable(const IniDocument& doc, const IniSection& s, const std::string& name);
Obstacle parseObstacle(const IniDocument& doc, const IniSection& s, const std::string& name);
PlacedObject parseObject(const IniDocument& doc, const IniSection& s, const std::string& name);
MissionSpec parseMission(const IniDocument& doc, const IniSection& s);
/** Cross-checks: objects on existing tables and inside their tops, mission names exist. */
void checkReferences(const IniDocument& doc, const World& w);
}  // namespace mrolr::world::detail
