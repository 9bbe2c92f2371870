// Cost of one EKF-SLAM measurement update against the number of features N: MRPT's kfEKFNaive and
// kfEKFAlaDavison (through BenchKalmanFilter), the postponed-update tracking step (thesis appendix
// C) and the step followed by its catch-up. Prints the ratio table at the end
// (docs/slam-postponed.md).

#include "BenchKalmanFilter.h"
#include "PostponedRunner.h"
#include "RatioReporter.h"

#include <benchmark/benchmark.h>

#include <iostream>

namespace
{
using mrolr::bench::BenchKalmanFilter;
using mrolr::bench::BenchProblem;
using mrolr::bench::PostponedRunner;

void runMrpt(benchmark::State& state, mrpt::bayes::TKFMethod method)
{
	BenchProblem problem(static_cast<int>(state.range(0)));
	BenchKalmanFilter filter(problem, method);
	for (auto _ : state) filter.step(0);
	benchmark::DoNotOptimize(filter.internal_getXkk()[0]);
	state.counters["N"] = static_cast<double>(state.range(0));
}

void BM_MrptNaive(benchmark::State& state)
{
	runMrpt(state, mrpt::bayes::kfEKFNaive);
}
void BM_MrptAlaDavison(benchmark::State& state)
{
	runMrpt(state, mrpt::bayes::kfEKFAlaDavison);
}

void BM_PostponedStep(benchmark::State& state)
{
	BenchProblem problem(static_cast<int>(state.range(0)));
	PostponedRunner runner(problem, 0);
	for (auto _ : state) runner.step();
	runner.catchUp();
	benchmark::DoNotOptimize(runner.state()[0]);
	state.counters["N"] = static_cast<double>(state.range(0));
}

void BM_PostponedStepAndCatchUp(benchmark::State& state)
{
	BenchProblem problem(static_cast<int>(state.range(0)));
	PostponedRunner runner(problem, 0);
	for (auto _ : state)
	{
		runner.step();
		runner.catchUp();
	}
	benchmark::DoNotOptimize(runner.state()[0]);
	state.counters["N"] = static_cast<double>(state.range(0));
}

void featureCounts(benchmark::internal::Benchmark* b)
{
	for (int N : {10, 50, 100, 300, 1000}) b->Arg(N);
	b->Unit(benchmark::kMicrosecond)->MinTime(0.2);
}

BENCHMARK(BM_MrptNaive)->Apply(featureCounts);
BENCHMARK(BM_MrptAlaDavison)->Apply(featureCounts);
BENCHMARK(BM_PostponedStep)->Apply(featureCounts);
BENCHMARK(BM_PostponedStepAndCatchUp)->Apply(featureCounts);

}  // namespace

int main(int argc, char** argv)
{
	benchmark::Initialize(&argc, argv);
	if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 2;
	mrolr::bench::RatioReporter reporter;
	benchmark::RunSpecifiedBenchmarks(&reporter);
	reporter.printTable(std::cout);
	benchmark::Shutdown();
	return 0;
}
