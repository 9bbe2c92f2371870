// Reading and writing the robot's plan (maps/<world>/plan.ini).
#include <mrolr/mission/Plan.h>
#include <mrolr/util/Config.h>
#include <mrolr/util/IniFields.h>

#include <opencv2/imgcodecs.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>

namespace mrolr::mission
{
namespace
{
namespace fs = std::filesystem;
using util::IniDocument;
using util::IniEntry;
using util::IniSection;

const IniSection& requireSection(const IniDocument& doc, const std::string& name)
{
	if (const auto* s = doc.find(name)) return *s;
	throw util::IniError(doc.path + ": missing section [" + name + "]");
}

NamedPose parseWaypoint(const IniDocument& doc, const IniSection& s, const IniEntry& e)
{
	if (util::fieldsOf(e).size() != 3) doc.fail(s, e, "expected 'z_m x_m phi_deg'");
	const auto v = util::numbers(doc, s, e, 3);
	return {e.key, {v[0], v[1], v[2] * M_PI / 180.0}};
}

/** Waypoint names of key @p key of [plan], each of which must be a waypoint. */
std::vector<NamedPose> namedPoses(const IniDocument& doc, const IniSection& s,
                                  const std::string& key, const Plan& p)
{
	const IniEntry& e = util::require(doc, s, key);
	std::string text = e.value;
	for (char& c : text)
		if (c == ';') c = ' ';
	std::vector<NamedPose> out;
	for (const auto& name : util::splitFields(text))
	{
		const NamedPose* w = p.findWaypoint(name);
		if (!w) doc.fail(s, e, "no waypoint '" + name + "' in [waypoints]");
		out.push_back(*w);
	}
	if (out.empty()) doc.fail(s, e, "at least one waypoint name is needed");
	return out;
}

PlanFeature parseFeature(const IniDocument& doc, const IniSection& s, const IniEntry& e)
{
	const auto f = util::fieldsOf(e);
	if (f.size() != 7) doc.fail(s, e, "expected 'X Y Z PATCH.png sigma_X sigma_Y sigma_Z'");
	PlanFeature k;
	k.id = e.key;
	for (int i = 0; i < 3; ++i)
	{
		k.p_FinW[i] = util::numberField(doc, s, e, f[i]);
		k.sigma_m[i] = util::numberField(doc, s, e, f[4 + i]);
		if (!(k.sigma_m[i] >= 0)) doc.fail(s, e, "a standard deviation must not be negative");
	}
	k.patch_file = f[3];
	const fs::path png = fs::path(doc.path).parent_path() / k.patch_file;
	k.patch = cv::imread(png.string(), cv::IMREAD_GRAYSCALE);
	if (k.patch.empty()) doc.fail(s, e, "cannot read the patch '" + png.string() + "'");
	return k;
}

PlanTable parseTable(const IniDocument& doc, const IniSection& s, const std::string& name)
{
	util::rejectUnknownKeys(doc, s, {"centre_m", "yaw_deg", "size_m"});
	const auto c = util::requireNumbers(doc, s, "centre_m", 2);
	const auto size = util::requireNumbers(doc, s, "size_m", 3);
	PlanTable t{name,    c[0],    c[1],   util::optionalNumbers(doc, s, "yaw_deg", {0})[0],
	            size[0], size[1], size[2]};
	if (t.length_m <= 0 || t.depth_m <= 0 || t.top_height_m <= 0)
		doc.fail(s, util::require(doc, s, "size_m"), "sizes must be positive");
	return t;
}

PlanRoom parseRoom(const IniDocument& doc, const IniSection& s)
{
	util::rejectUnknownKeys(doc, s, {"min_m", "max_m"});
	const auto lo = util::requireNumbers(doc, s, "min_m", 2);
	const auto hi = util::requireNumbers(doc, s, "max_m", 2);
	if (!(hi[0] > lo[0] && hi[1] > lo[1]))
		doc.fail(s, util::require(doc, s, "max_m"), "each of x and z must exceed min_m's");
	return {lo[0], lo[1], hi[0], hi[1]};
}

void readSections(const IniDocument& doc, Plan& p)
{
	for (const auto& s : doc.sections)
	{
		if (s.name == "waypoints")
			for (const auto& e : s.entries) p.waypoints.push_back(parseWaypoint(doc, s, e));
		else if (s.name == "known_features")
			for (const auto& e : s.entries) p.known_features.push_back(parseFeature(doc, s, e));
		else if (s.name == "known_feature_views")
			continue;  // read after every feature (readViews)
		else if (s.name.rfind("table.", 0) == 0 && s.name.size() > 6)
			p.tables.push_back(parseTable(doc, s, s.name.substr(6)));
		else if (s.name == "room")
			p.room = parseRoom(doc, s);
		else if (s.name != "plan")
			throw util::IniError(doc.path + ":" + std::to_string(s.line) + " [" + s.name +
			                     "]: unknown section (expected plan, waypoints, known_features, "
			                     "known_feature_views, table.NAME or room)");
	}
}

void readViews(const IniDocument& doc, Plan& p)
{
	const IniSection* s = doc.find("known_feature_views");
	if (!s) return;
	for (const auto& e : s->entries)
	{
		auto k = std::find_if(p.known_features.begin(), p.known_features.end(),
		                      [&](const PlanFeature& f) { return f.id == e.key; });
		if (k == p.known_features.end()) doc.fail(*s, e, "no known feature of this id");
		const auto v = util::numbers(doc, *s, e, 3);
		k->p_viewinW = Eigen::Vector3d(v[0], v[1], v[2]);
	}
}

std::string formatPose(const NamedPose& w)
{
	std::ostringstream s;
	s << std::setprecision(10) << w.xv_zxphi.x() << " " << w.xv_zxphi.y() << " "
	  << w.xv_zxphi.z() * 180.0 / M_PI;
	return s.str();
}

std::string names(const std::vector<NamedPose>& poses)
{
	std::string out;
	for (const auto& p : poses) out += (out.empty() ? "" : " ") + p.name;
	return out;
}
}  // namespace

double PlanRoom::wallDistance(const Eigen::Vector2d& p_zx) const
{
	const double z = p_zx.x(), x = p_zx.y();
	return std::min({x - min_x_m, max_x_m - x, z - min_z_m, max_z_m - z});
}

const NamedPose* Plan::findWaypoint(const std::string& name) const
{
	for (const auto& w : waypoints)
		if (w.name == name) return &w;
	return nullptr;
}

Plan Plan::fromDocument(const IniDocument& doc)
{
	Plan p;
	p.path = doc.path;
	readSections(doc, p);
	readViews(doc, p);
	const IniSection& plan = requireSection(doc, "plan");
	util::rejectUnknownKeys(doc, plan, {"route", "stations", "home"});
	p.route = namedPoses(doc, plan, "route", p);
	p.stations = namedPoses(doc, plan, "stations", p);
	const auto home = namedPoses(doc, plan, "home", p);
	if (home.size() != 1) doc.fail(plan, util::require(doc, plan, "home"), "one waypoint name");
	p.home = home.front();
	return p;
}

Plan Plan::load(const std::string& path, const std::vector<PlanOverride>& overrides)
{
	IniDocument doc = IniDocument::load(path);
	for (const auto& [section, key, value] : overrides) doc.set(section, key, value);
	return fromDocument(doc);
}

void Plan::save(const std::string& file) const
{
	const fs::path dir = fs::path(file).parent_path();
	std::ofstream out(file);
	if (!out) throw std::runtime_error(file + ": cannot write the plan");
	out << "# The robot's plan of this place (docs/mission.md \"Plan and map\"). W: x left, y up, "
	       "z forward, metres.\n[plan]\nroute = "
	    << names(route) << "\nstations = " << names(stations) << "\nhome = " << home.name
	    << "\n\n# z_m x_m phi_deg\n[waypoints]\n";
	for (const auto& w : waypoints) out << w.name << " = " << formatPose(w) << "\n";
	out << "\n# id = X Y Z PATCH.png sigma_X sigma_Y sigma_Z (m; the robot's own estimates)\n"
	       "[known_features]\n"
	    << std::setprecision(6);
	for (const auto& k : known_features)
	{
		fs::create_directories((dir / k.patch_file).parent_path());
		if (!cv::imwrite((dir / k.patch_file).string(), k.patch))
			throw std::runtime_error((dir / k.patch_file).string() + ": cannot write the patch");
		out << k.id << " = " << k.p_FinW.x() << " " << k.p_FinW.y() << " " << k.p_FinW.z() << " "
		    << k.patch_file << " " << k.sigma_m.x() << " " << k.sigma_m.y() << " " << k.sigma_m.z()
		    << "\n";
	}
	out << "\n# the head centre each patch was saved from, X Y Z (m)\n[known_feature_views]\n";
	for (const auto& k : known_features)
		if (k.p_viewinW)
			out << k.id << " = " << k.p_viewinW->x() << " " << k.p_viewinW->y() << " "
			    << k.p_viewinW->z() << "\n";
	for (const auto& t : tables)
		out << "\n[table." << t.name << "]\ncentre_m = " << t.x_m << " " << t.z_m
		    << "\nyaw_deg = " << t.yaw_deg << "\nsize_m = " << t.length_m << " " << t.depth_m << " "
		    << t.top_height_m << "\n";
	if (room)
		out << "\n# the walls: the floor's corners, x z (m)\n[room]\nmin_m = " << room->min_x_m
		    << " " << room->min_z_m << "\nmax_m = " << room->max_x_m << " " << room->max_z_m
		    << "\n";
	if (!out) throw std::runtime_error(file + ": cannot write the plan");
}

}  // namespace mrolr::mission
