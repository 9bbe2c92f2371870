// Wall time of the default mission (config/mission_sim.ini, stereo rendering off: that is the
// simulator's cost, not the link's) with driver = sim, and through the serial drivers on
// pseudo-terminals served by the simulated lab (SerialEmulation), in the same run: the ratio is
// the cost of real serial I/O for a whole mission.
#include <mrolr/mission/Mission.h>
#include <mrolr/mission/SerialEmulation.h>

#include <benchmark/benchmark.h>

#include <stdexcept>

using namespace mrolr;

namespace
{
mission::MissionOptions options()
{
	auto o = mission::MissionOptions::load(MROLR_SOURCE_DIR "/config/mission_sim.ini");
	o.search.render_stereo = false;
	o.search.scene_source = "simulated";  // no rendering: reconstruction needs the pairs
	return o;
}

void expectSuccess(const mission::MissionResult& r, benchmark::State& state)
{
	if (!r.success) state.SkipWithError(("mission failed: " + r.failure).c_str());
}
}  // namespace

static void BM_MissionSim(benchmark::State& state)
{
	const auto o = options();
	for (auto _ : state) expectSuccess(mission::Mission(o).run(), state);
}
BENCHMARK(BM_MissionSim)->Unit(benchmark::kMillisecond)->Iterations(10);

static void BM_MissionSerialEmulation(benchmark::State& state)
{
	const auto base = options();
	int resends = 0;
	for (auto _ : state)
	{
		auto o = base;
		auto lab = std::make_shared<mission::SimulatedLab>(o);
		mission::SerialEmulation emulation(*lab);
		emulation.useIn(o);
		const auto r = mission::Mission(o, lab).run();
		expectSuccess(r, state);
		for (const auto& l : r.links) resends += l.resends;
	}
	state.counters["resends"] = resends;
}
BENCHMARK(BM_MissionSerialEmulation)->Unit(benchmark::kMillisecond)->Iterations(10);

BENCHMARK_MAIN();
