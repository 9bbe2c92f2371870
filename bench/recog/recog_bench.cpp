// Recognition speed (issue 7): one model against a scene of about 200 segments, the 10-model
// database against the same scene, and OpenCV's point-pair-feature matcher
// (cv::ppf_match_3d::PPF3DDetector, the peer a user would otherwise pick) fed points with
// tangents sampled every 3 mm from the same wire-frames. The summary prints the ratios and the
// pose errors of both against the scene's truth, measured in the same run.
#include <mrolr/model/WireFrameSampling.h>
#include <mrolr/recog/Recognizer.h>
#include <mrolr/recog/SyntheticObjects.h>
#include <mrolr/recog/SyntheticScene.h>
#include <mrolr/recog/TransformCluster.h>

#include <benchmark/benchmark.h>
#include <opencv2/surface_matching.hpp>

#include <cstdio>
#include <map>
#include <memory>

using namespace mrolr::recog;

namespace
{
constexpr int kTarget = 1;  // the cup

struct Fixture
{
	std::vector<mrolr::model::WireFrame> objects = makeLabObjects();
	TableScene scene;
	std::vector<std::unique_ptr<Recognizer>> recognizers;
	cv::Mat ppf_scene;
	std::unique_ptr<cv::ppf_match_3d::PPF3DDetector> ppf;

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

void BM_RecogOneModel(benchmark::State& state)
{
	auto& f = fixture();
	for (auto _ : state) benchmark::DoNotOptimize(f.recognizers[kTarget]->recognize(f.scene.scene));
	state.counters["segments"] =
	    static_cast<double>(f.scene.scene.lines.size() + f.scene.scene.conics.size());
}
BENCHMARK(BM_RecogOneModel)->Unit(benchmark::kMillisecond);

void BM_RecogDatabase10(benchmark::State& state)
{
	auto& f = fixture();
	for (auto _ : state)
		for (const auto& r : f.recognizers) benchmark::DoNotOptimize(r->recognize(f.scene.scene));
}
BENCHMARK(BM_RecogDatabase10)->Unit(benchmark::kMillisecond);

void BM_RecogModelTables(benchmark::State& state)
{
	auto& f = fixture();
	for (auto _ : state)
		benchmark::DoNotOptimize(Recognizer(f.objects[kTarget], RecognitionOptions::defaults()));
}
BENCHMARK(BM_RecogModelTables)->Unit(benchmark::kMillisecond);

void BM_PpfMatchOneModel(benchmark::State& state)
{
	auto& f = fixture();
	for (auto _ : state)
	{
		std::vector<cv::ppf_match_3d::Pose3DPtr> results;
		f.ppf->match(f.ppf_scene, results, 1.0 / 10.0, 0.05);
		benchmark::DoNotOptimize(results);
	}
	state.counters["points"] = f.ppf_scene.rows;
}
BENCHMARK(BM_PpfMatchOneModel)->Unit(benchmark::kMillisecond);

/** Remembers each benchmark's CPU time (ms) for the summary. */
class SummaryReporter : public benchmark::ConsoleReporter
{
 public:
	std::map<std::string, double> ms;
	void ReportRuns(const std::vector<Run>& runs) override
	{
		for (const auto& r : runs) ms[r.benchmark_name()] = r.GetAdjustedCPUTime();
		ConsoleReporter::ReportRuns(runs);
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
	std::printf(
	    "summary (CPU time): one model %.2f ms, 10-model database %.2f ms, PPF one model %.2f ms; "
	    "time ratio MROLR/PPF = %.3f\n",
	    one, db, ppf, ppf > 0 ? one / ppf : 0.0);
	printAccuracy();
	benchmark::Shutdown();
	return 0;
}
