#include <mrolr/util/IniDocument.h>

#include <algorithm>
#include <fstream>
#include <sstream>

namespace mrolr::util
{
namespace
{
std::string trim(const std::string& s)
{
	const auto b = s.find_first_not_of(" \t\r\n");
	if (b == std::string::npos) return {};
	const auto e = s.find_last_not_of(" \t\r\n");
	return s.substr(b, e - b + 1);
}

/** Removes a trailing comment: '#' or ';' at the line start or after whitespace. */
std::string stripComment(const std::string& line)
{
	for (size_t i = 0; i < line.size(); ++i)
	{
		const bool marker = line[i] == '#' || line[i] == ';';
		if (marker && (i == 0 || line[i - 1] == ' ' || line[i - 1] == '\t'))
			return line.substr(0, i);
	}
	return line;
}

[[noreturn]] void failLine(const std::string& path, int line, const std::string& why)
{
	throw IniError(path + ":" + std::to_string(line) + ": " + why);
}

void addEntry(IniDocument& doc, const std::string& text, int line)
{
	if (doc.sections.empty())
		failLine(doc.path, line, "'" + text + "' appears before any [section]");
	const auto eq = text.find('=');
	if (eq == std::string::npos) failLine(doc.path, line, "'" + text + "' is not 'key = value'");
	IniEntry e{trim(text.substr(0, eq)), trim(text.substr(eq + 1)), line};
	IniSection& s = doc.sections.back();
	if (e.key.empty()) failLine(doc.path, line, "[" + s.name + "] empty key in '" + text + "'");
	if (s.find(e.key)) failLine(doc.path, line, "[" + s.name + "] " + e.key + " is defined twice");
	s.entries.push_back(e);
}

void addSection(IniDocument& doc, const std::string& text, int line)
{
	if (text.back() != ']') failLine(doc.path, line, "malformed section header '" + text + "'");
	const std::string name = trim(text.substr(1, text.size() - 2));
	if (name.empty()) failLine(doc.path, line, "empty section name");
	if (doc.find(name)) failLine(doc.path, line, "section [" + name + "] appears twice");
	doc.sections.push_back(IniSection{name, line, {}});
}
}  // namespace

const IniEntry* IniSection::find(const std::string& key) const
{
	for (const auto& e : entries)
		if (e.key == key) return &e;
	return nullptr;
}

IniDocument IniDocument::parse(const std::string& text, const std::string& path)
{
	IniDocument doc;
	doc.path = path;
	std::istringstream is(text);
	int line = 0;
	for (std::string raw; std::getline(is, raw);)
	{
		++line;
		const std::string t = trim(stripComment(raw));
		if (t.empty()) continue;
		if (t.front() == '[')
			addSection(doc, t, line);
		else
			addEntry(doc, t, line);
	}
	return doc;
}

IniDocument IniDocument::load(const std::string& path)
{
	std::ifstream f(path);
	if (!f) throw IniError(path + ": cannot open file");
	std::ostringstream os;
	os << f.rdbuf();
	return parse(os.str(), path);
}

const IniSection* IniDocument::find(const std::string& name) const
{
	for (const auto& s : sections)
		if (s.name == name) return &s;
	return nullptr;
}

void IniDocument::set(const std::string& section, const std::string& key, const std::string& value)
{
	auto s = std::find_if(sections.begin(), sections.end(),
	                      [&](const IniSection& x) { return x.name == section; });
	if (s == sections.end()) s = sections.insert(sections.end(), IniSection{section, 0, {}});
	for (auto& e : s->entries)
		if (e.key == key)
		{
			e.value = value, e.line = 0;
			return;
		}
	s->entries.push_back(IniEntry{key, value, 0});
}

std::string IniDocument::describe(const IniSection& s, const IniEntry& e) const
{
	const std::string where = e.line > 0 ? path + ":" + std::to_string(e.line) : path + " (--set)";
	return where + " [" + s.name + "] " + e.key + " = '" + e.value + "'";
}

void IniDocument::fail(const IniSection& s, const IniEntry& e, const std::string& why) const
{
	throw IniError(describe(s, e) + ": " + why);
}

}  // namespace mrolr::util
