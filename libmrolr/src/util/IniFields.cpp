#include <mrolr/util/Config.h>
#include <mrolr/util/IniFields.h>

#include <algorithm>
#include <cctype>

namespace mrolr::util
{
std::vector<std::string> fieldsOf(const IniEntry& e)
{
	return splitFields(e.value);
}

double numberField(const IniDocument& doc, const IniSection& s, const IniEntry& e,
                   const std::string& text)
{
	double v = 0;
	if (!parseDouble(text, v)) doc.fail(s, e, "'" + text + "' is not a number");
	return v;
}

std::vector<double> numbers(const IniDocument& doc, const IniSection& s, const IniEntry& e,
                            size_t count)
{
	const auto f = fieldsOf(e);
	if (f.size() != count)
		doc.fail(s, e,
		         "expected " + std::to_string(count) + " numbers, got " + std::to_string(f.size()));
	std::vector<double> out;
	for (const auto& t : f) out.push_back(numberField(doc, s, e, t));
	return out;
}

const IniEntry& require(const IniDocument& doc, const IniSection& s, const std::string& key)
{
	const IniEntry* e = s.find(key);
	if (!e)
		throw IniError(doc.path + ":" + std::to_string(s.line) + " [" + s.name + "] " + key +
		                 ": missing key");
	return *e;
}

std::vector<double> requireNumbers(const IniDocument& doc, const IniSection& s,
                                   const std::string& key, size_t count)
{
	return numbers(doc, s, require(doc, s, key), count);
}

std::vector<double> optionalNumbers(const IniDocument& doc, const IniSection& s,
                                    const std::string& key, const std::vector<double>& fallback)
{
	const IniEntry* e = s.find(key);
	return e ? numbers(doc, s, *e, fallback.size()) : fallback;
}

std::string optionalString(const IniSection& s, const std::string& key, const std::string& fallback)
{
	const IniEntry* e = s.find(key);
	return e ? e->value : fallback;
}

bool optionalBool(const IniDocument& doc, const IniSection& s, const std::string& key,
                  bool fallback)
{
	const IniEntry* e = s.find(key);
	if (!e) return fallback;
	std::string v = e->value;
	std::transform(v.begin(), v.end(), v.begin(), [](unsigned char c) { return std::tolower(c); });
	if (v == "true" || v == "yes" || v == "1") return true;
	if (v == "false" || v == "no" || v == "0") return false;
	doc.fail(s, *e, "not a boolean (true/false)");
}

void rejectUnknownKeys(const IniDocument& doc, const IniSection& s,
                       const std::vector<std::string>& allowed)
{
	for (const auto& e : s.entries)
		if (std::find(allowed.begin(), allowed.end(), e.key) == allowed.end())
			doc.fail(s, e, "unknown key in this section");
}

}  // namespace mrolr::util
