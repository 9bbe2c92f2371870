// Loading and checking the mission configuration (docs/mission.md "Configuration").
#include <mrolr/mission/MissionOptions.h>
#include <mrolr/util/Config.h>

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
util::ConfigFile openNamed(const CConfigFileBase& cfg, const std::string& section,
                                    const std::string& key, const std::string& base_dir)
{
	const auto path = resolve(base_dir, util::readString(cfg, section, key));
	return util::openConfigFile(path, util::describeKey(cfg, section, key));
}

/** Keys that moved out of the mission file: a clear error instead of a silent no-op. */
void rejectMovedKeys(const CConfigFileBase& cfg)
{
	const char* moved[][3] = {
	    {"mission", "world_file", "the world is the simulator's: [simulator] world_file or --world"},
	    {"mission", "route", "the route is in the plan ([mission] plan, [plan] route)"},
	    {"mission", "search_stations", "the stations are in the plan ([plan] stations)"},
	    {"mission", "home_waypoint", "home is in the plan ([plan] home)"},
	    {"navigation", "measurement_source", "renamed landmark_sensor (images | ideal_sim)"},
	    {"search", "scene_source", "renamed scene_sensor (reconstructed | exact_sim)"}};
	for (const auto& m : moved)
		if (util::hasKey(cfg, m[0], m[1]))
			throw util::ConfigError(util::describeKey(cfg, m[0], m[1]) + ": no longer read: " +
			                        m[2]);
}

NavigationMode readMode(const CConfigFileBase& cfg)
{
	const auto m = util::readString(cfg, "mission", "mode");
	if (m == "slam") return NavigationMode::Slam;
	if (m == "dead_reckoning") return NavigationMode::DeadReckoning;
	throw util::ConfigError(util::describeKey(cfg, "mission", "mode") + ": '" + m +
	                        "' is not slam or dead_reckoning");
}

/** The target is a model of the robot's model database, never a world's object. */
void readTarget(const CConfigFileBase& cfg, const std::string& dir, MissionOptions& o)
{
	o.models_dir = resolve(dir, util::readString(cfg, "files", "models_dir"));
	if (!fs::is_directory(o.models_dir))
		throw util::ConfigError(util::describeKey(cfg, "files", "models_dir") + ": '" +
		                        o.models_dir + "' is not a folder");
	o.target = util::readString(cfg, "mission", "target");
	const auto file = resolve(o.models_dir, o.target + ".wf");
	if (!std::ifstream(file).good())
		throw util::ConfigError(util::describeKey(cfg, "mission", "target") + ": no model '" +
		                        o.target + "' in the model database (" + file +
		                        " cannot be opened)");
}

void readPlan(const CConfigFileBase& cfg, const std::string& dir,
              const MissionOptions::PlanChoice& choice, MissionOptions& o)
{
	o.plan_file = choice.file.empty() ? resolve(dir, util::readString(cfg, "mission", "plan"))
	                                  : choice.file;
	o.plan = Plan::load(o.plan_file, choice.overrides);
}

void readMissionSection(const CConfigFileBase& cfg, const std::string& dir,
                        const MissionOptions::PlanChoice& plan, MissionOptions& o)
{
	rejectMovedKeys(cfg);
	o.name = util::readString(cfg, "mission", "name");
	readPlan(cfg, dir, plan, o);
	readTarget(cfg, dir, o);
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
	// single-feature hypotheses on the estimated table top (ObjectSearch), as the recogniser
	// was measured
	o.recognition.plane.loadFromConfigFile(openNamed(cfg, "files", "recognition_file", dir),
	                                       "plane_hypotheses");
	const auto rtx = openNamed(cfg, "files", "arm_file", dir);
	o.rtx.loadFromConfigFile(rtx, "rtx");
	o.grasp.loadFromConfigFile(rtx, "arm_grasp");
	o.marker.loadFromConfigFile(rtx, "arm_marker");
}
/** measurement_source = images: the vision area's [vision] and its filter ([slam], with the
 * covariance R of image measurements) from [files] vision_file; the head constants stay. */
void readVisionFile(const CConfigFileBase& cfg, const std::string& dir, MissionOptions& o)
{
	const auto vf = openNamed(cfg, "files", "vision_file", dir);
	o.vision.loadFromConfigFile(vf, "vision");
	if (o.navigation.image_nssd_ambiguity_margin >= 0)
		o.vision.nssd_ambiguity_margin = o.navigation.image_nssd_ambiguity_margin;
	slam::SlamOptions filter;  // the vision file's filter alone: its absent keys are defaults
	filter.loadFromConfigFile(vf, "slam");
	filter.head = o.slam.head;
	o.slam = filter;
}
}  // namespace

MissionOptions MissionOptions::fromConfig(const CConfigFileBase& cfg, const std::string& base_dir,
                                          const PlanChoice& plan)
{
	MissionOptions o;
	o.devices.loadFromConfigFile(cfg);
	readMissionSection(cfg, base_dir, plan, o);
	readModelFiles(cfg, base_dir, o);
	o.dock.loadFromConfigFile(cfg, "arm_mount");
	o.navigation.loadFromConfigFile(cfg, "navigation");
	if (o.navigation.max_rotation_step_deg > 0)
		o.trajectory.max_rotation_step_deg = o.navigation.max_rotation_step_deg;
	o.search.loadFromConfigFile(cfg, "search");
	if (o.navigation.landmark_source == LandmarkSource::Images) readVisionFile(cfg, base_dir, o);
	const bool reconstructed = o.search.scene_source == SceneSource::Reconstructed;
	if (reconstructed)
		o.scene.loadFromConfigFile(openNamed(cfg, "files", "scene_file", base_dir), "scene");
	if (reconstructed && o.search.image_verification)
		o.image_verification.loadFromConfigFile(
		    openNamed(cfg, "files", "recognition_file", base_dir), "image_verification");
	o.retrieval.loadFromConfigFile(cfg, "retrieval");
	o.docking.loadFromConfigFile(cfg, "docking");
	o.place.loadFromConfigFile(cfg, "place");
	o.dock_calibration.loadFromConfigFile(cfg, "dock_calibration");
	return o;
}

MissionOptions MissionOptions::load(const std::string& path, const PlanChoice& plan)
{
	const auto cfg = util::openConfigFile(path);
	auto o = fromConfig(cfg, fs::path(path).parent_path().string(), plan);
	o.config_path = path;
	return o;
}

void MissionOptions::dump(std::ostream& out) const
{
	out << "[mission]\nname = " << name << "\nplan = " << plan_file << "\ntarget = " << target
	    << "\nmode = " << (mode == NavigationMode::Slam ? "slam" : "dead_reckoning")
	    << "\nseed = " << seed << "\nhome_tolerance_m = " << home_tolerance_m
	    << "\n\n[files]\nmodels_dir = " << models_dir << "\n\n[navigation]\n";
	navigation.dump(out);
	out << "\n[search]\n";
	search.dump(out);
	out << "\n[retrieval]\n";
	retrieval.dump(out);
	out << "\n[docking]\n";
	docking.dump(out);
	out << "\n[place]\n";
	place.dump(out);
	out << "\n[dock_calibration]\n";
	dock_calibration.dump(out);
	out << "\n";
	devices.dump(out);
}

}  // namespace mrolr::mission
