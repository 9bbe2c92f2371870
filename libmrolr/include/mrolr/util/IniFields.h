#pragma once
/** Typed reading of IniDocument values ("1.2 3 -4", "known", colours) with errors that name file,
 * line, section, key and value. */

#include <mrolr/util/IniDocument.h>

#include <string>
#include <vector>

namespace mrolr::util
{
/** The whitespace/comma separated fields of an entry's value. */
std::vector<std::string> fieldsOf(const IniEntry& e);

/** Parses field @p text as a finite number or fails naming the entry. */
double numberField(const IniDocument& doc, const IniSection& s, const IniEntry& e,
                   const std::string& text);

/** Exactly @p count numbers from the whole value. */
std::vector<double> numbers(const IniDocument& doc, const IniSection& s, const IniEntry& e,
                            size_t count);

/** The entry with @p key in @p s; fails naming the section and key when missing. */
const IniEntry& require(const IniDocument& doc, const IniSection& s, const std::string& key);

/** Exactly @p count numbers from key @p key (required). */
std::vector<double> requireNumbers(const IniDocument& doc, const IniSection& s,
                                   const std::string& key, size_t count);

/** Numbers from key @p key if present, else @p fallback (whose size sets the count). */
std::vector<double> optionalNumbers(const IniDocument& doc, const IniSection& s,
                                    const std::string& key, const std::vector<double>& fallback);

/** The string value of @p key if present, else @p fallback. */
std::string optionalString(const IniSection& s, const std::string& key,
                           const std::string& fallback);

/** A boolean (true/false, yes/no, 1/0) from @p key if present, else @p fallback. */
bool optionalBool(const IniDocument& doc, const IniSection& s, const std::string& key,
                  bool fallback);

/** Fails naming the section if it has a key not in @p allowed (catches typos in key names). */
void rejectUnknownKeys(const IniDocument& doc, const IniSection& s,
                       const std::vector<std::string>& allowed);

}  // namespace mrolr::util
