#pragma once
/** The world files are read with util's ordered .ini reader; these names keep the world code's
 * vocabulary (a malformed world is a WorldError). */
#include <mrolr/util/IniDocument.h>
#include <mrolr/util/IniFields.h>

namespace mrolr::world
{
/** Thrown for any malformed world description (util::IniError). */
using WorldError = util::IniError;
using util::IniDocument;
using util::IniEntry;
using util::IniSection;

}  // namespace mrolr::world
