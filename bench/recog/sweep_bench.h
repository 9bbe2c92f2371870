#pragma once
// bench_recog's image-verified sweep (sweep_bench.cpp): every model of datasets/objects in the
// first five views of the rendered evaluation set, as the mission's sweep searches them.
#include <vector>

namespace mrolr::bench
{
/** Prints the sweep's CPU time from its repetitions (@p sweep_cpu_ms, ms: median and range, per
 * 10 models), each model and view's median wall time and each stage's mean (BM_RecogSweepImages
 * registers the benchmark itself). */
void printSweepBreakdown(const std::vector<double>& sweep_cpu_ms);
}  // namespace mrolr::bench
