// The default mission as users run it, in the same run: in process (`mrolr-mission`) and across
// ROS 1 nodes on loopback (`scripts/ros-mission.sh --no-bag`: a master, mrolr-ros-lab and
// mrolr-ros-robot), wall time of the whole command each. Ratio: ROS / in process (target ≤ 2).
#include <benchmark/benchmark.h>

#include <sys/wait.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <string>

namespace
{
const std::string kRoot = MROLR_SOURCE_DIR;
const std::string kBin = MROLR_BIN_DIR;
double g_in_process_s = 0, g_ros_s = 0;

/** Runs @p cmd, returns its wall time in seconds; a failure is the benchmark's error. */
double timed(const std::string& cmd, benchmark::State& state)
{
	const auto t0 = std::chrono::steady_clock::now();
	const int rc = std::system((cmd + " > /dev/null 2>&1").c_str());
	const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
	if (rc != 0) state.SkipWithError(("failed: " + cmd).c_str());
	return s;
}

std::string outDir(const std::string& name)
{
	const auto d = std::filesystem::temp_directory_path() / ("mrolr_bench_" + name);
	std::filesystem::remove_all(d);
	return d.string();
}
}  // namespace

static void BM_MissionInProcess(benchmark::State& state)
{
	for (auto _ : state)
	{
		const double s = timed("cd " + kRoot + " && " + kBin + "/mrolr-mission --quiet --out " +
		                           outDir("in_process"),
		                       state);
		state.SetIterationTime(s);
		g_in_process_s = s;
	}
}
BENCHMARK(BM_MissionInProcess)->Unit(benchmark::kSecond)->UseManualTime()->Iterations(1);

static void BM_MissionRosNodes(benchmark::State& state)
{
	for (auto _ : state)
	{
		const double s = timed("cd " + kRoot + " && MROLR_BIN=" + kBin +
		                           " scripts/ros-mission.sh --no-bag --out " + outDir("ros"),
		                       state);
		state.SetIterationTime(s);
		g_ros_s = s;
	}
	if (g_in_process_s > 0) state.counters["ratio_to_in_process"] = g_ros_s / g_in_process_s;
}
BENCHMARK(BM_MissionRosNodes)->Unit(benchmark::kSecond)->UseManualTime()->Iterations(1);

int main(int argc, char** argv)
{
	benchmark::Initialize(&argc, argv);
	benchmark::RunSpecifiedBenchmarks();
	if (g_in_process_s > 0 && g_ros_s > 0)
		std::cout << "ROS mission / in-process mission, wall time: " << g_ros_s << " s / "
		          << g_in_process_s << " s = " << g_ros_s / g_in_process_s << " (target <= 2)\n";
	benchmark::Shutdown();
	return 0;
}
