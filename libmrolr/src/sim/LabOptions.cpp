// The simulated lab's configuration: the world side's sections of a mission file.
#include <mrolr/sim/Lab.h>
#include <mrolr/util/Config.h>

#include <mrpt/config/CConfigFile.h>

#include <filesystem>
#include <fstream>

namespace mrolr::sim
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

util::ConfigFile openNamed(const CConfigFileBase& cfg, const std::string& key,
                                    const std::string& base_dir)
{
	const auto path = resolve(base_dir, util::readString(cfg, "files", key));
	return util::openConfigFile(path, util::describeKey(cfg, "files", key));
}

/** A different noise stream per run: frame k of a run renders with seed + k. */
constexpr unsigned kRenderSeedStride = 1000003;
}  // namespace

bool LabOptions::namesWorld(const CConfigFileBase& cfg)
{
	return util::hasKey(cfg, "simulator", "world_file");
}

LabOptions LabOptions::load(const CConfigFileBase& cfg, const std::string& base_dir,
                            const std::string& world_file)
{
	LabOptions o;
	o.world_file = world_file.empty()
	                   ? resolve(base_dir, util::readString(cfg, "simulator", "world_file"))
	                   : world_file;
	o.world = world::World::load(o.world_file);
	if (o.world.waypoints.empty())
		throw util::ConfigError(o.world_file + ": the world has no [waypoints] (no start pose)");
	o.labmate.loadFromConfigFile(openNamed(cfg, "labmate_file", base_dir), "labmate");
	o.bisight.loadFromConfigFile(openNamed(cfg, "bisight_file", base_dir), "bisight");
	const auto arm_file = openNamed(cfg, "arm_file", base_dir);
	o.rtx.loadFromConfigFile(arm_file, "rtx");
	o.gripper.loadFromConfigFile(arm_file, "arm_grasp");
	o.marker.loadFromConfigFile(arm_file, "arm_marker");
	o.mount.loadFromConfigFile(cfg, "arm_mount");
	o.seed = static_cast<unsigned>(util::readInt(cfg, "mission", "seed"));
	o.base.seed = o.seed;
	o.base.loadFromConfigFile(cfg, "sim_base");
	o.arm.open_width_mm = o.gripper.gripper_opening_max_mm;
	o.arm.loadFromConfigFile(cfg, "sim_arm");
	o.gripper_physics.loadFromConfigFile(cfg, "sim_gripper");
	o.render.noise_sigma_grey = 2.0;
	o.render.seed = o.seed * kRenderSeedStride;
	o.render.loadFromConfigFile(cfg, "sim_render");
	o.head_move_time_s = util::readDouble(cfg, "simulator", "head_move_time_s", o.head_move_time_s);
	util::requireInRange(cfg, "simulator", "head_move_time_s", o.head_move_time_s, 0, 60);
	return o;
}

}  // namespace mrolr::sim
