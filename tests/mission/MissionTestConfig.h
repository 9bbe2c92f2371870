#pragma once
// The shipped mission files in memory, for tests that override keys, and a whole in-process run
// as mrolr-mission does it: the robot side on the simulated lab's devices, then eval.
#include "../common/FreshTempDir.h"

#include <mrolr/apps/SimulatedWorld.h>
#include <mrolr/eval/MissionEval.h>
#include <mrolr/mission/Mission.h>
#include <mrolr/mission/MissionDevices.h>
#include <mrolr/mission/MissionOptions.h>
#include <mrolr/util/Config.h>
#include <mrolr/mission/MissionOutputs.h>

#include <mrpt/config/CConfigFileMemory.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace mrolr::mission::test
{
using mrolr::test_support::freshTempDir;

inline std::string configDir()
{
	return std::string(MROLR_SOURCE_DIR) + "/config";
}

/** A mission file of config/ in memory, its base files laid in (keys can be overridden without
 * touching the file). */
inline mrpt::config::CConfigFileMemory missionConfig(const std::string& file)
{
	return mrpt::config::CConfigFileMemory(util::openConfigFile(configDir() + "/" + file).getContent());
}

inline mrpt::config::CConfigFileMemory defaultMissionConfig()
{
	return missionConfig("mission_sim.ini");
}

inline MissionOptions optionsFrom(const mrpt::config::CConfigFileBase& cfg,
                                  const MissionOptions::PlanChoice& plan = {})
{
	return MissionOptions::fromConfig(cfg, configDir(), plan);
}

/** The plan with overrides: {{"plan", "route", "W0"}, {"waypoints", "S2", "2.45 0 180"}}. */
inline MissionOptions::PlanChoice planWith(std::vector<PlanOverride> overrides,
                                           const std::string& file = "")
{
	return {file, std::move(overrides)};
}

/** A short mission: straight from the start to the table and home (no lap). */
inline MissionOptions::PlanChoice shortRoute()
{
	return planWith({{"plan", "route", "W0"}});
}

/** One whole in-process run and its evaluation. */
struct Run
{
	MissionOptions o;
	MissionResult r;
	nlohmann::json report;  ///< report.json: the robot's report with eval's checks
	eval::MissionTruth truth;
};

inline Run runMission(const mrpt::config::CConfigFileBase& cfg,
                      const MissionOptions::PlanChoice& plan = {}, const std::string& world_file = "")
{
	Run run;
	run.o = optionsFrom(cfg, plan);
	apps::SimulatedWorld world(cfg, configDir(), run.o, world_file);
	MissionDevices devices(run.o.devices, world.devices());
	run.r = Mission(run.o, devices.devices(), world.sensors()).run();
	run.truth = eval::truthOf(world.lab());
	run.report = reportJson(run.r, run.o);
	eval::evaluateMission(run.report, run.truth);
	return run;
}

/** Whether a note of @p r's timeline contains @p text. */
inline bool timelineHas(const MissionResult& r, const std::string& text)
{
	for (const auto& e : r.timeline.events())
		if (e.text.find(text) != std::string::npos) return true;
	return false;
}

/** The true pose at every step of @p run, in the robot's path order (matched by base time). */
inline std::vector<Eigen::Vector3d> truePath(const Run& run)
{
	std::vector<Eigen::Vector3d> out;
	size_t k = 0;
	for (const auto& s : run.r.path)
	{
		while (k + 1 < run.truth.steps.size() &&
		       run.truth.steps[k + 1].time_s <= s.device_time_s + 1e-9)
			++k;
		out.push_back(run.truth.steps[k].xv_zxphi);
	}
	return out;
}

}  // namespace mrolr::mission::test
