// Loading and checking the mission configuration (docs/mission.md "Configuration").
#include <mrolr/mission/MissionOptions.h>
#include <mrolr/util/Config.h>
#include <mrolr/world/World.h>

#include <mrpt/config/CConfigFile.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <ostream>

namespace mrolr::mission
{
namespace
{
namespace fs = std::filesystem;
using mrpt::config::CConfigFileBase;

std::string resolve(const std::string& base_dir, const std::string& file)
{
	const fs::path p(file);
	return (p.is_absolute() ? p : fs::path(base_dir) / p).lexically_normal().string();
}

/** Opens the file a key names, with the key in the error if it cannot be read. */
mrpt::config::CConfigFile openNamed(const CConfigFileBase& cfg, const std::string& section,
                                    const std::string& key, const std::string& base_dir)
{
	const auto path = resolve(base_dir, util::readString(cfg, section, key));
	if (!std::ifstream(path).good())
		throw util::ConfigError(util::describeKey(cfg, section, key) + ": cannot open '" + path +
		                        "'");
	return mrpt::config::CConfigFile(path);
}

std::string trimmed(const std::string& s)
{
	const auto a = s.find_first_not_of(" \t");
	if (a == std::string::npos) return "";
	return s.substr(a, s.find_last_not_of(" \t") - a + 1);
}

std::vector<std::string> splitOn(const std::string& text, char sep)
{
	std::vector<std::string> out;
	size_t start = 0;
	while (start <= text.size())
	{
		const auto end = std::min(text.find(sep, start), text.size());
		if (auto t = trimmed(text.substr(start, end - start)); !t.empty()) out.push_back(t);
		start = end + 1;
	}
	return out;
}

NamedPose waypointPose(const world::Waypoint& w)
{
	return {w.name, {w.z_m, w.x_m, w.phi_rad}};
}

NamedPose parseStation(const CConfigFileBase& cfg, const std::string& key, const std::string& text,
                       const world::World& w, size_t index)
{
	const auto fields = util::splitFields(text);
	if (fields.size() == 1)
	{
		const auto* wp = w.findWaypoint(fields[0]);
		if (!wp)
			throw util::ConfigError(util::describeKey(cfg, "mission", key) + ": no waypoint '" +
			                        fields[0] + "' in " + w.path);
		return waypointPose(*wp);
	}
	double v[3];
	if (fields.size() != 3 || !util::parseDouble(fields[0], v[0]) ||
	    !util::parseDouble(fields[1], v[1]) || !util::parseDouble(fields[2], v[2]))
		throw util::ConfigError(util::describeKey(cfg, "mission", key) + ": station '" + text +
		                        "' is neither a waypoint name nor 'z x phi_deg'");
	return {"S" + std::to_string(index + 1), {v[0], v[1], v[2] * M_PI / 180.0}};
}

std::vector<std::string> readRoute(const CConfigFileBase& cfg, const world::World& w)
{
	const auto names = util::splitFields(util::readString(cfg, "mission", "route"));
	if (names.size() == 1 && names[0] == "world")
	{
		std::vector<std::string> all;
		for (const auto& wp : w.waypoints) all.push_back(wp.name);
		return all;
	}
	for (const auto& n : names)
		if (!w.findWaypoint(n))
			throw util::ConfigError(util::describeKey(cfg, "mission", "route") + ": no waypoint '" +
			                        n + "' in " + w.path);
	return names;
}

NavigationMode readMode(const CConfigFileBase& cfg)
{
	const auto m = util::readString(cfg, "mission", "mode");
	if (m == "slam") return NavigationMode::Slam;
	if (m == "dead_reckoning") return NavigationMode::DeadReckoning;
	throw util::ConfigError(util::describeKey(cfg, "mission", "mode") + ": '" + m +
	                        "' is not slam or dead_reckoning");
}

void readTarget(const CConfigFileBase& cfg, MissionOptions& o)
{
	o.target = util::hasKey(cfg, "mission", "target") ? util::readString(cfg, "mission", "target")
	                                                  : o.world.mission.target;
	if (const auto* placed = o.world.findObject(o.target)) o.target = placed->model;
	if (o.target.empty())
		throw util::ConfigError(util::describeKey(cfg, "mission", "target") +
		                        ": no target and the world has no [mission] target");
	const auto file = resolve(o.world.objects_dir, o.target + ".ini");
	if (!std::ifstream(file).good())
		throw util::ConfigError(util::describeKey(cfg, "mission", "target") + ": no model '" +
		                        o.target + "' (" + file + " cannot be opened)");
	o.target_model_file = file;
}

void readHomeAndStations(const CConfigFileBase& cfg, MissionOptions& o)
{
	o.home_waypoint = util::hasKey(cfg, "mission", "home_waypoint")
	                      ? util::readString(cfg, "mission", "home_waypoint")
	                      : o.world.mission.home_waypoint;
	if (!o.world.findWaypoint(o.home_waypoint))
		throw util::ConfigError(util::describeKey(cfg, "mission", "home_waypoint") +
		                        ": no waypoint '" + o.home_waypoint + "' in " + o.world.path);
	const auto items = splitOn(util::readString(cfg, "mission", "search_stations"), ';');
	if (items.empty())
		throw util::ConfigError(util::describeKey(cfg, "mission", "search_stations") +
		                        ": at least one station is needed");
	for (size_t i = 0; i < items.size(); ++i)
		o.stations.push_back(parseStation(cfg, "search_stations", items[i], o.world, i));
}

void readMissionSection(const CConfigFileBase& cfg, const std::string& dir, MissionOptions& o)
{
	o.name = util::readString(cfg, "mission", "name");
	o.world_file = resolve(dir, util::readString(cfg, "mission", "world_file"));
	o.world = world::World::load(o.world_file);
	readTarget(cfg, o);
	o.route = readRoute(cfg, o.world);
	readHomeAndStations(cfg, o);
	o.mode = readMode(cfg);
	o.obstacle_mode = util::readBool(cfg, "mission", "obstacle_mode", false);
	if (o.obstacle_mode) o.obstacle.loadFromConfigFile(cfg, "obstacle");
	o.seed = static_cast<unsigned>(util::readInt(cfg, "mission", "seed"));
	o.home_tolerance_m = util::readDouble(cfg, "mission", "home_tolerance_m");
}

void readModelFiles(const CConfigFileBase& cfg, const std::string& dir, MissionOptions& o)
{
	const auto lab = openNamed(cfg, "files", "labmate_file", dir);
	o.labmate.loadFromConfigFile(lab, "labmate");
	o.trajectory.loadFromConfigFile(lab, "trajectory");
	const auto head = openNamed(cfg, "files", "bisight_file", dir);
	o.bisight.loadFromConfigFile(head, "bisight");
	o.slam.head.loadFromConfigFile(head, "bisight");
	o.slam.loadFromConfigFile(openNamed(cfg, "files", "slam_file", dir), "slam");
	o.recognition.loadFromConfigFile(openNamed(cfg, "files", "recognition_file", dir),
	                                 "recognition");
	const auto rtx = openNamed(cfg, "files", "arm_file", dir);
	o.rtx.loadFromConfigFile(rtx, "rtx");
	o.grasp.loadFromConfigFile(rtx, "arm_grasp");
}
/** measurement_source = images: the vision area's [vision] and its filter ([slam], with the
 * covariance R of image measurements) from [files] vision_file; the head constants stay. */
void readVisionFile(const CConfigFileBase& cfg, const std::string& dir, MissionOptions& o)
{
	const auto vf = openNamed(cfg, "files", "vision_file", dir);
	o.vision.loadFromConfigFile(vf, "vision");
	if (o.navigation.image_nssd_ambiguity_margin >= 0)
		o.vision.nssd_ambiguity_margin = o.navigation.image_nssd_ambiguity_margin;
	const auto head = o.slam.head;
	o.slam.loadFromConfigFile(vf, "slam");
	o.slam.head = head;
}
}  // namespace

MissionOptions MissionOptions::fromConfig(const CConfigFileBase& cfg, const std::string& base_dir)
{
	MissionOptions o;
	o.devices.loadFromConfigFile(cfg);
	readMissionSection(cfg, base_dir, o);
	readModelFiles(cfg, base_dir, o);
	o.dock.loadFromConfigFile(cfg, "arm_mount");
	o.sim_base.loadFromConfigFile(cfg, "sim_base");
	o.sim_arm.loadFromConfigFile(cfg, "sim_arm");
	o.navigation.loadFromConfigFile(cfg, "navigation");
	if (o.navigation.max_rotation_step_deg > 0)
		o.trajectory.max_rotation_step_deg = o.navigation.max_rotation_step_deg;
	o.search.loadFromConfigFile(cfg, "search");
	if (o.navigation.measurement_source == "images") readVisionFile(cfg, base_dir, o);
	if (o.search.scene_source == "reconstructed")
		o.scene.loadFromConfigFile(openNamed(cfg, "files", "scene_file", base_dir), "scene");
	if (o.search.scene_source == "reconstructed" && o.search.image_verification)
		o.image_verification.loadFromConfigFile(
		    openNamed(cfg, "files", "recognition_file", base_dir), "image_verification");
	o.retrieval.loadFromConfigFile(cfg, "retrieval");
	return o;
}

MissionOptions MissionOptions::load(const std::string& path)
{
	if (!std::ifstream(path).good())
		throw util::ConfigError("cannot open mission configuration '" + path + "'");
	mrpt::config::CConfigFile cfg(path);
	auto o = fromConfig(cfg, fs::path(path).parent_path().string());
	o.config_path = path;
	return o;
}

void MissionOptions::dump(std::ostream& out) const
{
	out << "[mission]\nname = " << name << "\nworld_file = " << world_file
	    << "\ntarget = " << target << "\nhome_waypoint = " << home_waypoint
	    << "\nmode = " << (mode == NavigationMode::Slam ? "slam" : "dead_reckoning")
	    << "\nseed = " << seed << "\nhome_tolerance_m = " << home_tolerance_m << "\nroute =";
	for (const auto& r : route) out << " " << r;
	out << "\nsearch_stations =";
	for (size_t i = 0; i < stations.size(); ++i)
		out << (i ? "; " : " ") << stations[i].xv_zxphi.x() << " " << stations[i].xv_zxphi.y()
		    << " " << stations[i].xv_zxphi.z() * 180 / M_PI;
	out << "\n\n[navigation]\n";
	navigation.dump(out);
	out << "\n[search]\n";
	search.dump(out);
	out << "\n[retrieval]\n";
	retrieval.dump(out);
	out << "\n";
	devices.dump(out);
}

}  // namespace mrolr::mission
