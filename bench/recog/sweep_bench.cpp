// bench_recog's image-verified sweep: the fixture, its benchmark (repeated: one sweep is one
// iteration of about a second) and the summary of its repetitions with each stage's time.
#include "sweep_bench.h"

#include <mrolr/eval/RecognitionEvaluation.h>
#include <mrolr/recog/Recognizer.h>
#include <mrolr/recog/images/ImageVerifier.h>
#include <mrolr/util/Cli.h>

#include <benchmark/benchmark.h>
#include <mrpt/config/CConfigFile.h>

#include <algorithm>
#include <cstdio>
#include <memory>
#include <vector>

using namespace mrolr::recog;

namespace mrolr::bench
{
namespace
{
/** The first kSweepViews scenes of the rendered evaluation set and every model of datasets/objects
 * (config/recognition.ini's options), searched as the mission's sweep does: with each view's
 * stereo pair, up direction and table plane. */
struct RenderedSweep
{
	static constexpr int kSweepViews = 5;
	std::vector<mrolr::eval::EvalScene> views;
	std::vector<std::unique_ptr<ImageVerifier>> images;
	std::vector<std::unique_ptr<Recognizer>> models;

	RenderedSweep()
	{
		const mrpt::config::CConfigFile cfg(
		    mrolr::util::requireProjectFile("config/recognition.ini"));
		mrolr::eval::EvaluationOptions eo;
		eo.loadFromConfigFile(cfg, "evaluation");
		ImageVerificationOptions io;
		io.loadFromConfigFile(cfg, "image_verification");
		RecognitionOptions ro;
		ro.loadFromConfigFile(cfg, "recognition");
		ro.plane.loadFromConfigFile(cfg, "plane_hypotheses");
		const auto gen = mrolr::eval::makeSceneGenerator(eo);
		for (int k = 0; k < kSweepViews; ++k)
		{
			views.push_back(gen->make(k));
			const auto& v = views.back();
			images.push_back(std::make_unique<ImageVerifier>(v.left, v.right, v.calib, io));
		}
		for (const auto& wf : mrolr::eval::databaseModels(*gen, {}))
			models.push_back(std::make_unique<Recognizer>(wf, ro));
	}

	RecognitionResult search(size_t model, size_t view) const
	{
		const auto& v = views[view];
		return models[model]->recognize(v.scene, {v.up_L, std::cref(*images[view]), v.plane_L});
	}
};

RenderedSweep& sweep()
{
	static RenderedSweep f;
	return f;
}

/** Every model of the database in every view of the sweep, verified in the images. One sweep takes
 * about a second, so a run of it is one iteration: it is repeated, and the summary gives the
 * median of the repetitions with their range (on a shared machine single runs spread by ±15 %). */
constexpr int kSweepRepetitions = 7;

void BM_RecogSweepImages(benchmark::State& state)
{
	auto& f = sweep();
	for (auto _ : state)
		for (size_t v = 0; v < f.views.size(); ++v)
			for (size_t m = 0; m < f.models.size(); ++m) benchmark::DoNotOptimize(f.search(m, v));
	state.counters["models"] = static_cast<double>(f.models.size());
	state.counters["views"] = static_cast<double>(f.views.size());
}
BENCHMARK(BM_RecogSweepImages)->Unit(benchmark::kMillisecond)->Repetitions(kSweepRepetitions);

}  // namespace

namespace
{
/** The median of @p xs (the upper one of an even count). */
double medianOf(std::vector<double> xs)
{
	std::sort(xs.begin(), xs.end());
	return xs.empty() ? 0.0 : xs[xs.size() / 2];
}

}  // namespace

/** The sweep's CPU time per repetition (@p sweep_cpu_ms: median, range), then each model in each
 * view searched again kSweepRepetitions times outside the timing loop: the median and the 90th
 * percentile over the models and views of each one's median wall time in the process, and each
 * stage's mean. */
void printSweepBreakdown(const std::vector<double>& sweep_cpu_ms)
{
	const auto& f = sweep();
	std::vector<std::vector<double>> each(f.views.size() * f.models.size());
	RecognitionTimes sum;
	int found = 0, refinements = 0, reused = 0, sweeps_reused = 0;
	for (int rep = 0; rep < kSweepRepetitions; ++rep)
		for (size_t v = 0; v < f.views.size(); ++v)
			for (size_t m = 0; m < f.models.size(); ++m)
			{
				const RecognitionResult r = f.search(m, v);
				each[v * f.models.size() + m].push_back(r.ms), sum += r.times;
				if (rep > 0) continue;
				found += r.found ? 1 : 0;
				refinements += r.image_refinements, reused += r.image_refinements_reused;
				sweeps_reused += r.image_sweeps_reused;
			}
	std::vector<double> ms;
	for (const auto& e : each) ms.push_back(medianOf(e));
	std::sort(ms.begin(), ms.end());
	const auto n = static_cast<double>(ms.size());
	const RecognitionTimes mean = sum.scaled(1 / (n * kSweepRepetitions));
	const double cpu = medianOf(sweep_cpu_ms), per10 = 10.0 / static_cast<double>(f.models.size());
	const auto [lo, hi] = std::minmax_element(sweep_cpu_ms.begin(), sweep_cpu_ms.end());
	std::printf(
	    "image-verified sweep: %zu models x %zu views in %.0f ms CPU, median of %zu runs "
	    "(%.0f-%.0f ms); %.0f ms per 10 models (%.0f-%.0f; target 1000); per model and view "
	    "median %.1f ms (target 20), 90th percentile %.1f ms; %d found\n",
	    f.models.size(), f.views.size(), cpu, sweep_cpu_ms.size(), *lo, *hi, cpu * per10,
	    *lo * per10, *hi * per10, ms[ms.size() / 2], ms[static_cast<size_t>(0.9 * (n - 1))], found);
	std::printf(
	    "  mean per model and view: cliques %.1f ms, 3D verification %.1f ms, image scores %.1f "
	    "ms, image refinement %.1f ms, plane hypotheses %.1f ms (sum %.1f ms)\n",
	    mean.cliques_ms, mean.verify_3d_ms, mean.image_score_ms, mean.image_refine_ms,
	    mean.plane_ms, mean.total_ms());
	std::printf(
	    "  refinements in the images per model and view: %.2f made (%.2f yaw circles of theirs "
	    "taken from an earlier one), %.2f reused\n",
	    refinements / n, sweeps_reused / n, reused / n);
}

}  // namespace mrolr::bench
