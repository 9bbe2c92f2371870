// Recognition speed: one model against a scene of about 200 segments, the 10-model database
// against the same scene, and OpenCV's point-pair-feature matcher (cv::ppf_match_3d::PPF3DDetector,
// the peer a user would otherwise pick) fed points with tangents sampled every 3 mm from the same
// wire-frames; then recognition verified in the stereo images: every model of datasets/objects
// in the first five views of the rendered evaluation set, as the mission's sweep searches them,
// with the time of each stage. The summary prints the ratios and the pose errors of MROLR and PPF
// against the scene's truth, measured in the same run.
#include "sweep_bench.h"

#include <mrolr/eval/RecognitionEvaluation.h>
#include <mrolr/model/WireFrameIO.h>
#include <mrolr/model/WireFrameSampling.h>
#include <mrolr/recog/Recognizer.h>
#include <mrolr/recog/TransformCluster.h>
#include <mrolr/sim/SyntheticObjects.h>
#include <mrolr/sim/SyntheticScene.h>
#include <mrolr/util/Cli.h>

#include <benchmark/benchmark.h>
#include <mrpt/config/CConfigFile.h>
#include <opencv2/surface_matching.hpp>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <map>
#include <memory>

using namespace mrolr::recog;
using namespace mrolr::sim;
namespace model = mrolr::model;

namespace
{
constexpr int kTarget = 1;  // the cup
constexpr int kAbsent = 7;  // the wedge: left out of the absent-model scene

RecognitionOptions withSkip(bool skip)
{
	RecognitionOptions o = RecognitionOptions::defaults();
	o.skip_hopeless_levels = skip;
	return o;
}

struct Fixture
{
	std::vector<mrolr::model::WireFrame> objects = makeLabObjects();
	TableScene scene;
	std::vector<std::unique_ptr<Recognizer>> recognizers;
	cv::Mat ppf_scene;
	std::unique_ptr<cv::ppf_match_3d::PPF3DDetector> ppf;
	model::WireFrame absent_scene;  ///< the nine objects other than kAbsent
	std::unique_ptr<Recognizer> absent_skip, absent_full;

	Fixture()
	{
		SceneNoise n;
		n.endpoint_sigma_mm = 0.5, n.fragment_probability = 0.35, n.missing_fraction = 0.05;
		scene = makeTableScene(objects, kTarget, 9, n, 2024);
		for (const auto& o : objects)
			recognizers.push_back(std::make_unique<Recognizer>(o, RecognitionOptions::defaults()));
		ppf_scene = pointsWithTangents(scene.scene);
		ppf = std::make_unique<cv::ppf_match_3d::PPF3DDetector>(0.03, 0.05);
		ppf->trainModel(pointsWithTangents(objects[kTarget]));
		std::vector<model::WireFrame> others = objects;
		others.erase(others.begin() + kAbsent);
		absent_scene = makeTableScene(others, -1, 9, n, 2025).scene;
		absent_skip = std::make_unique<Recognizer>(objects[kAbsent], withSkip(true));
		absent_full = std::make_unique<Recognizer>(objects[kAbsent], withSkip(false));
	}

	/** N × 6 float matrix (x y z tx ty tz) of samples every 3 mm, as PPF3DDetector expects. */
	static cv::Mat pointsWithTangents(const mrolr::model::WireFrame& wf)
	{
		const auto s = mrolr::model::sampleWireFrame(wf, 3.0);
		cv::Mat m(static_cast<int>(s.size()), 6, CV_32F);
		for (int i = 0; i < m.rows; ++i)
			for (int j = 0; j < 3; ++j)
				m.at<float>(i, j) = static_cast<float>(s[i].p[j]),
				               m.at<float>(i, 3 + j) = static_cast<float>(s[i].tangent[j]);
		return m;
	}
};

Fixture& fixture()
{
	static Fixture f;
	return f;
}

/** Scene 0 of the rendered evaluation set (config/recognition.ini [evaluation]) and the first
 * lab model (datasets/objects) that is not in it, with PPF trained on that model. */
struct RenderedFixture
{
	mrolr::eval::EvalScene scene;
	model::WireFrame absent;
	std::unique_ptr<Recognizer> skip, full;
	cv::Mat ppf_scene;
	std::unique_ptr<cv::ppf_match_3d::PPF3DDetector> ppf;
	ImageVerificationOptions image_options;
	std::unique_ptr<ImageVerifier> images;  ///< the scene's stereo pair

	RenderedFixture()
	{
		const mrpt::config::CConfigFile cfg(
		    mrolr::util::requireProjectFile("config/recognition.ini"));
		mrolr::eval::EvaluationOptions eo;
		eo.loadFromConfigFile(cfg, "evaluation");
		image_options.loadFromConfigFile(cfg, "image_verification");
		scene = mrolr::eval::makeSceneGenerator(eo)->make(0);
		images =
		    std::make_unique<ImageVerifier>(scene.left, scene.right, scene.calib, image_options);
		for (const char* name : {"alphabet_cube", "bottle", "can", "cup", "drink_package",
		                         "hole_punch", "large_cup", "stapler"})
			if (!scene.find(name) && absent.name.empty())
				absent = model::loadWireFrame(mrolr::util::requireProjectFile(
				    std::string("datasets/objects/") + name + ".wf"));
		skip = std::make_unique<Recognizer>(absent, withSkip(true));
		full = std::make_unique<Recognizer>(absent, withSkip(false));
		ppf_scene = Fixture::pointsWithTangents(scene.scene);
		ppf = std::make_unique<cv::ppf_match_3d::PPF3DDetector>(0.03, 0.05);
		ppf->trainModel(Fixture::pointsWithTangents(absent));
	}
};

RenderedFixture& rendered()
{
	static RenderedFixture f;
	return f;
}

/** Times one recognition of @p scene; counters: found, levels skipped, scene segments. */
void timeRecognition(benchmark::State& state, const Recognizer& rec, const model::WireFrame& scene)
{
	RecognitionResult r;
	for (auto _ : state) benchmark::DoNotOptimize(r = rec.recognize(scene));
	state.counters["found"] = r.found;
	state.counters["levels_skipped"] = r.levels_skipped;
	state.counters["segments"] = static_cast<double>(scene.lines.size() + scene.conics.size());
}

/** Times PPF3DDetector::match (scene step 1/10, distance 0.05) on @p points. */
void timePpf(benchmark::State& state, cv::ppf_match_3d::PPF3DDetector& ppf, const cv::Mat& points)
{
	for (auto _ : state)
	{
		std::vector<cv::ppf_match_3d::Pose3DPtr> results;
		ppf.match(points, results, 1.0 / 10.0, 0.05);
		benchmark::DoNotOptimize(results);
	}
	state.counters["points"] = points.rows;
}

/** The absent model in the rendered, reconstructed scene: with (1) and without (0) skips. */
void BM_RecogAbsentRendered(benchmark::State& state)
{
	auto& f = rendered();
	timeRecognition(state, state.range(0) ? *f.skip : *f.full, f.scene.scene);
}
BENCHMARK(BM_RecogAbsentRendered)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

/** The same absent model searched with verification in the scene's stereo images (the edge maps
 * built once per scene, BM_ImageEdgeMaps). */
void BM_RecogAbsentRenderedImages(benchmark::State& state)
{
	auto& f = rendered();
	for (auto _ : state)
		benchmark::DoNotOptimize(
		    f.skip->recognize(f.scene.scene, {f.scene.up_L, std::cref(*f.images), std::nullopt}));
}
BENCHMARK(BM_RecogAbsentRenderedImages)->Unit(benchmark::kMillisecond);

/** Canny, distance transform and edge directions of one stereo pair (once per scene). */
void BM_ImageEdgeMaps(benchmark::State& state)
{
	auto& f = rendered();
	for (auto _ : state)
		benchmark::DoNotOptimize(
		    ImageVerifier(f.scene.left, f.scene.right, f.scene.calib, f.image_options));
}
BENCHMARK(BM_ImageEdgeMaps)->Unit(benchmark::kMillisecond);

/** One hypothesis scored in both images (the absent model at the first object's true pose). */
void BM_ImageScoreOneHypothesis(benchmark::State& state)
{
	auto& f = rendered();
	const auto& samples = f.skip->sightedSamples(f.image_options.sample_spacing_mm);
	for (auto _ : state)
		benchmark::DoNotOptimize(f.images->score(samples, f.scene.objects.front().T_OinL));
}
BENCHMARK(BM_ImageScoreOneHypothesis)->Unit(benchmark::kMillisecond);

void BM_PpfAbsentRendered(benchmark::State& state)
{
	timePpf(state, *rendered().ppf, rendered().ppf_scene);
}
BENCHMARK(BM_PpfAbsentRendered)->Unit(benchmark::kMillisecond);

void BM_RecogOneModel(benchmark::State& state)
{
	timeRecognition(state, *fixture().recognizers[kTarget], fixture().scene.scene);
}
BENCHMARK(BM_RecogOneModel)->Unit(benchmark::kMillisecond);

void BM_RecogDatabase10(benchmark::State& state)
{
	auto& f = fixture();
	for (auto _ : state)
		for (const auto& r : f.recognizers) benchmark::DoNotOptimize(r->recognize(f.scene.scene));
}
BENCHMARK(BM_RecogDatabase10)->Unit(benchmark::kMillisecond);

/** A model absent from the scene, with (1) and without (0) the support bound's skips. */
void BM_RecogAbsentModel(benchmark::State& state)
{
	auto& f = fixture();
	timeRecognition(state, state.range(0) ? *f.absent_skip : *f.absent_full, f.absent_scene);
}
BENCHMARK(BM_RecogAbsentModel)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

void BM_RecogModelTables(benchmark::State& state)
{
	auto& f = fixture();
	for (auto _ : state)
		benchmark::DoNotOptimize(Recognizer(f.objects[kTarget], RecognitionOptions::defaults()));
}
BENCHMARK(BM_RecogModelTables)->Unit(benchmark::kMillisecond);

void BM_PpfMatchOneModel(benchmark::State& state)
{
	timePpf(state, *fixture().ppf, fixture().ppf_scene);
}
BENCHMARK(BM_PpfMatchOneModel)->Unit(benchmark::kMillisecond);

/** Remembers each benchmark's CPU time (ms) for the summary: of a repeated one, every
 * repetition's. */
class SummaryReporter : public benchmark::ConsoleReporter
{
 public:
	std::map<std::string, double> ms;  ///< the last run's
	/// every run's, in order, by the benchmark's function name (without its /repeats:N)
	std::map<std::string, std::vector<double>> runs;
	void ReportRuns(const std::vector<Run>& rs) override
	{
		for (const auto& r : rs)
			if (r.run_type == Run::RT_Iteration)
				ms[r.benchmark_name()] = r.GetAdjustedCPUTime(),
				runs[r.run_name.function_name].push_back(r.GetAdjustedCPUTime());
		ConsoleReporter::ReportRuns(rs);
	}
};

Eigen::Isometry3d bestPpfPose(const cv::Mat& scene)
{
	std::vector<cv::ppf_match_3d::Pose3DPtr> results;
	fixture().ppf->match(scene, results, 1.0 / 10.0, 0.05);
	Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
	if (results.empty()) return T;
	for (int i = 0; i < 3; ++i)
		for (int j = 0; j < 4; ++j) T.matrix()(i, j) = results[0]->pose(i, j);
	return T;
}

void printError(const char* what, const Eigen::Isometry3d& T, const Eigen::Isometry3d& truth)
{
	std::printf("%s: rotation error %.2f deg, translation error %.2f mm\n", what,
	            rotationDistanceDeg(T.linear(), truth.linear()),
	            (T.translation() - truth.translation()).norm());
}

void printAccuracy()
{
	auto& f = fixture();
	printError("MROLR cup in the scene", f.recognizers[kTarget]->recognize(f.scene.scene).T_OinS,
	           f.scene.T_OinS);
	printError("PPF cup in the scene (best pose)", bestPpfPose(f.ppf_scene), f.scene.T_OinS);
	// The cup alone, noise-free: whether PPF on wire-frame points works at all without clutter.
	const auto alone = placeInScene(f.objects[kTarget], f.scene.T_OinS);
	printError("PPF cup alone (best pose)", bestPpfPose(Fixture::pointsWithTangents(alone)),
	           f.scene.T_OinS);
}
}  // namespace

int main(int argc, char** argv)
{
	benchmark::Initialize(&argc, argv);
	if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
	SummaryReporter reporter;  // CPU time: the machine is shared, wall time is not reproducible
	benchmark::RunSpecifiedBenchmarks(&reporter);
	auto get = [&](const char* n) { return reporter.ms.count(n) ? reporter.ms[n] : 0.0; };
	const double one = get("BM_RecogOneModel"), db = get("BM_RecogDatabase10"),
	             ppf = get("BM_PpfMatchOneModel");
	const double abs0 = get("BM_RecogAbsentModel/0"), abs1 = get("BM_RecogAbsentModel/1");
	const double rend0 = get("BM_RecogAbsentRendered/0"), rend1 = get("BM_RecogAbsentRendered/1"),
	             rppf = get("BM_PpfAbsentRendered");
	std::printf(
	    "absent model (CPU time): synthetic scene %.2f ms without skips, %.2f ms with; "
	    "rendered scene %.2f ms without, %.2f ms with, PPF %.2f ms; ratio MROLR (with "
	    "skips) / PPF on the rendered scene = %.3f\n",
	    abs0, abs1, rend0, rend1, rppf, rppf > 0 ? rend1 / rppf : 0.0);
	const double rimg = get("BM_RecogAbsentRenderedImages"), maps = get("BM_ImageEdgeMaps"),
	             hyp = get("BM_ImageScoreOneHypothesis");
	std::printf(
	    "image verification (CPU time): absent model on the rendered scene %.2f ms (3D only "
	    "%.2f ms; ratio to PPF %.3f), edge maps of the pair %.2f ms, one hypothesis %.3f ms\n",
	    rimg, rend1, rppf > 0 ? rimg / rppf : 0.0, maps, hyp);
	std::printf(
	    "summary (CPU time): one model %.2f ms, 10-model database %.2f ms, PPF one model %.2f ms; "
	    "time ratio MROLR/PPF = %.3f\n",
	    one, db, ppf, ppf > 0 ? one / ppf : 0.0);
	if (reporter.runs.count("BM_RecogSweepImages"))
		mrolr::bench::printSweepBreakdown(reporter.runs["BM_RecogSweepImages"]);
	printAccuracy();
	benchmark::Shutdown();
	return 0;
}
