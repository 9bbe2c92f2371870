#include <mrolr/util/IniFields.h>
#include <mrolr/world/ObjectShape.h>
#include <mrolr/world/StrokeFont.h>

#include <algorithm>

namespace mrolr::world
{
namespace
{
Eigen::Vector3d vec3(const std::vector<double>& v)
{
	return {v[0], v[1], v[2]};
}

void requirePositive(const IniDocument& doc, const IniSection& s, const std::string& key, double v)
{
	if (v <= 0) doc.fail(s, require(doc, s, key), "must be positive");
}

double positive(const IniDocument& doc, const IniSection& s, const std::string& key)
{
	const double v = requireNumbers(doc, s, key, 1)[0];
	requirePositive(doc, s, key, v);
	return v;
}

Eigen::Vector3d partColour(const IniDocument& doc, const IniSection& s)
{
	const Eigen::Vector3d c = vec3(optionalNumbers(doc, s, "colour", {0.8, 0.8, 0.8}));
	if (c.minCoeff() < 0 || c.maxCoeff() > 1) doc.fail(s, *s.find("colour"), "must be in [0, 1]");
	return c;
}

void parseFrustum(const IniDocument& doc, const IniSection& s, ShapePart& p)
{
	p.kind = ShapePart::Kind::Frustum;
	p.height_mm = positive(doc, s, "height_mm");
	if (s.find("radius_mm"))
		p.radius_bottom_mm = p.radius_top_mm = positive(doc, s, "radius_mm");
	else
	{
		p.radius_bottom_mm = requireNumbers(doc, s, "radius_bottom_mm", 1)[0];
		p.radius_top_mm = requireNumbers(doc, s, "radius_top_mm", 1)[0];
		if (p.radius_bottom_mm < 0 || p.radius_top_mm < 0 ||
		    p.radius_bottom_mm + p.radius_top_mm <= 0)
			doc.fail(s, require(doc, s, "radius_top_mm"), "radii must be >= 0, not both 0");
	}
}

ShapePart parsePart(const IniDocument& doc, const IniSection& s, const std::string& name)
{
	rejectUnknownKeys(doc, s,
	                  {"type", "base_mm", "yaw_deg", "size_mm", "height_mm", "radius_mm",
	                   "radius_bottom_mm", "radius_top_mm", "thickness_mm", "width_mm", "colour"});
	ShapePart p;
	p.name = name;
	p.base_mm = vec3(requireNumbers(doc, s, "base_mm", 3));
	p.yaw_deg = optionalNumbers(doc, s, "yaw_deg", {0.0})[0];
	p.colour = partColour(doc, s);
	const IniEntry& type = require(doc, s, "type");
	if (type.value == "box")
	{
		p.size_mm = vec3(requireNumbers(doc, s, "size_mm", 3));
		if (p.size_mm.minCoeff() <= 0) doc.fail(s, require(doc, s, "size_mm"), "must be positive");
	}
	else if (type.value == "cylinder" || type.value == "cone")
		parseFrustum(doc, s, p);
	else if (type.value == "handle")
	{
		p.kind = ShapePart::Kind::Handle;
		p.radius_mm = positive(doc, s, "radius_mm");
		p.thickness_mm = positive(doc, s, "thickness_mm");
		p.width_mm = positive(doc, s, "width_mm");
	}
	else
		doc.fail(s, type, "type must be box, cylinder, cone or handle");
	return p;
}

Marking parseMarking(const IniDocument& doc, const IniSection& s, const std::string& name,
                     const ObjectShape& o)
{
	rejectUnknownKeys(doc, s, {"part", "face", "letter", "height_mm", "stroke_mm", "colour"});
	Marking m;
	m.name = name;
	const IniEntry& part = require(doc, s, "part");
	m.part = part.value;
	const ShapePart* p = o.findPart(m.part);
	if (!p || p->kind != ShapePart::Kind::Box)
		doc.fail(s, part, "must name a box part defined above it");
	const IniEntry& face = require(doc, s, "face");
	const std::vector<std::string> faces{"+x", "-x", "+y", "-y", "+z"};
	if (std::find(faces.begin(), faces.end(), face.value) == faces.end())
		doc.fail(s, face, "face must be +x, -x, +y, -y or +z");
	m.face = face.value;
	const IniEntry& letter = require(doc, s, "letter");
	if (letter.value.size() != 1 || !hasStrokeLetter(letter.value[0]))
		doc.fail(s, letter, "must be one letter of A E F H I K L M N T V W X Y Z");
	m.letter = letter.value[0];
	m.height_mm = optionalNumbers(doc, s, "height_mm", {30.0})[0];
	m.stroke_mm = optionalNumbers(doc, s, "stroke_mm", {4.0})[0];
	m.colour = s.find("colour") ? partColour(doc, s) : Eigen::Vector3d(0.05, 0.05, 0.05);
	return m;
}

void parseGrasp(const IniDocument& doc, const IniSection& s, ObjectShape& o)
{
	rejectUnknownKeys(doc, s, {"p_mm", "yaw_deg", "pitch_deg", "roll_deg"});
	o.has_grasp = true;
	o.grasp_p_mm = vec3(requireNumbers(doc, s, "p_mm", 3));
	o.grasp_yaw_deg = optionalNumbers(doc, s, "yaw_deg", {0.0})[0];
	o.grasp_pitch_deg = optionalNumbers(doc, s, "pitch_deg", {0.0})[0];
	o.grasp_roll_deg = optionalNumbers(doc, s, "roll_deg", {0.0})[0];
}

void parseObjectSection(const IniDocument& doc, const IniSection& s, ObjectShape& o)
{
	const auto dot = s.name.find('.');
	const std::string kind = s.name.substr(0, dot);
	const std::string name = dot == std::string::npos ? "" : s.name.substr(dot + 1);
	if (s.name == "object")
		o.name = optionalString(s, "name", o.name);
	else if (s.name == "grasp")
		parseGrasp(doc, s, o);
	else if (kind == "part" && !name.empty())
		o.parts.push_back(parsePart(doc, s, name));
	else if (kind == "marking" && !name.empty())
		o.markings.push_back(parseMarking(doc, s, name, o));
	else
		throw WorldError(doc.path + ":" + std::to_string(s.line) + " [" + s.name +
		                 "]: unknown section (expected object, grasp, part.NAME, marking.NAME)");
}

ObjectShape fromDocument(const IniDocument& doc)
{
	ObjectShape o;
	o.path = doc.path;
	for (const auto& s : doc.sections) parseObjectSection(doc, s, o);
	if (o.parts.empty()) throw WorldError(doc.path + ": an object needs at least one [part.NAME]");
	if (o.name.empty()) throw WorldError(doc.path + ": [object] name is missing");
	return o;
}
}  // namespace

ObjectShape ObjectShape::parse(const std::string& text, const std::string& path)
{
	return fromDocument(IniDocument::parse(text, path));
}

ObjectShape ObjectShape::load(const std::string& path)
{
	return fromDocument(IniDocument::load(path));
}

const ShapePart* ObjectShape::findPart(const std::string& n) const
{
	for (const auto& p : parts)
		if (p.name == n) return &p;
	return nullptr;
}

double ObjectShape::heightMm() const
{
	double h = 0;
	for (const auto& p : parts)
	{
		const double top = p.kind == ShapePart::Kind::Box       ? p.size_mm.z()
		                   : p.kind == ShapePart::Kind::Frustum ? p.height_mm
		                                                        : p.radius_mm + p.thickness_mm / 2;
		h = std::max(h, p.base_mm.z() + top);
	}
	return h;
}

}  // namespace mrolr::world
