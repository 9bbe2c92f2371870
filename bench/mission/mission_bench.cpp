// Whole missions, in the same run: the short mission (start, table, home) with the simulator's
// shortcut sensors and no rendering, driven in process (driver = sim) and through the serial
// drivers on pseudo-terminals (the cost of real serial I/O); and the default mission (the lap from
// the robot's own images), whose robot compute per motion step and in all is reported apart from
// the simulator's rendering.
#include <mrolr/apps/SerialEmulation.h>
#include <mrolr/apps/SimulatedWorld.h>
#include <mrolr/mission/Mission.h>
#include <mrolr/mission/MissionDevices.h>

#include <benchmark/benchmark.h>
#include <mrpt/config/CConfigFile.h>

#include <algorithm>
#include <stdexcept>

using namespace mrolr;

namespace
{
const std::string kConfig = MROLR_SOURCE_DIR "/config/mission_sim.ini";
const std::string kConfigDir = MROLR_SOURCE_DIR "/config";

/** The mission file with the shortcut sensors (no rendering at all) or as shipped. */
mrpt::config::CConfigFile config(bool shortcuts)
{
	mrpt::config::CConfigFile cfg(kConfig);
	if (shortcuts)
	{
		cfg.write("navigation", "landmark_sensor", "ideal_sim");
		cfg.write("search", "scene_sensor", "exact_sim");
		cfg.write("search", "render_stereo", "false");
	}
	cfg.discardSavingChanges();
	return cfg;
}

mission::MissionOptions::PlanChoice shortRoute()
{
	return {"", {{"plan", "route", "W0"}}};
}

void expectSuccess(const mission::MissionResult& r, benchmark::State& state)
{
	if (!r.success) state.SkipWithError(("mission failed: " + r.failure).c_str());
}

mission::MissionResult runOnce(const mrpt::config::CConfigFileBase& cfg,
                               const mission::MissionOptions::PlanChoice& plan, bool serial)
{
	auto o = mission::MissionOptions::fromConfig(cfg, kConfigDir, plan);
	apps::SimulatedWorld world(cfg, kConfigDir, o);
	std::unique_ptr<apps::SerialEmulation> emulation;
	if (serial)
	{
		emulation = std::make_unique<apps::SerialEmulation>(world.lab());
		emulation->useIn(o);
	}
	mission::MissionDevices devices(o.devices, world.devices());
	return mission::Mission(o, devices.devices(), world.sensors()).run();
}

double median(std::vector<double> v)
{
	if (v.empty()) return 0;
	std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
	return v[v.size() / 2];
}
}  // namespace

static void BM_MissionSim(benchmark::State& state)
{
	const auto cfg = config(true);
	for (auto _ : state) expectSuccess(runOnce(cfg, shortRoute(), false), state);
}
BENCHMARK(BM_MissionSim)->Unit(benchmark::kMillisecond)->Iterations(10);

static void BM_MissionSerialEmulation(benchmark::State& state)
{
	const auto cfg = config(true);
	int resends = 0;
	for (auto _ : state)
	{
		const auto r = runOnce(cfg, shortRoute(), true);
		expectSuccess(r, state);
		for (const auto& l : r.links) resends += l.resends;
	}
	state.counters["resends"] = resends;
}
BENCHMARK(BM_MissionSerialEmulation)->Unit(benchmark::kMillisecond)->Iterations(10);

/** The default mission (the lap from images). Wall time includes the simulator's rendering;
 * the counters are the robot's own compute: in all, and the median per motion step. */
static void BM_MissionImages(benchmark::State& state)
{
	const auto cfg = config(false);
	double compute = 0, render = 0, per_step = 0;
	for (auto _ : state)
	{
		const auto r = runOnce(cfg, {}, false);
		expectSuccess(r, state);
		std::vector<double> steps;
		for (const auto& s : r.path) steps.push_back(s.compute_s);
		compute += r.timeline.computeSeconds(), render += r.timeline.renderSeconds();
		per_step = std::max(per_step, median(steps));
	}
	const double n = static_cast<double>(state.iterations());
	state.counters["robot_compute_s"] = compute / n;
	state.counters["render_s"] = render / n;
	state.counters["step_compute_median_ms"] = 1000 * per_step;
}
BENCHMARK(BM_MissionImages)->Unit(benchmark::kSecond)->Iterations(2);

BENCHMARK_MAIN();
