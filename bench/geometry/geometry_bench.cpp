// BiSight head geometry per call: projection with its 4×3 Jacobian, symmetric fixation, and
// triangulation (point only, and with covariance); the peer for triangulation is OpenCV's DLT
// cv::triangulatePoints on the same pixels and camera matrices. The summary line prints the ratio.
#include <mrolr/geometry/BiSightHead.h>

#include <benchmark/benchmark.h>
#include <opencv2/calib3d.hpp>
#include <opencv2/core/eigen.hpp>

#include <cstdio>
#include <map>
#include <random>
#include <string>
#include <vector>

namespace
{
using namespace mrolr::geometry;

constexpr int kPoints = 1000;

// kPoints points ahead, a fixed non-fixating head pose and their noisy pixels.
struct Scene
{
	BiSightHead head{BiSightOptions()};
	HeadAngles angles{0.05, -0.1, -0.04, 0.05};
	std::vector<Eigen::Vector3d> points;
	std::vector<StereoPixels> pixels;
	cv::Mat P_left, P_right, px_left, px_right;  // 3×4 projection matrices, 2×N pixels
};

cv::Mat projectionMatrix(const BiSightHead& head, Side side, const HeadAngles& a)
{
	// P = K [R | t] with the camera in the CV convention: same pixels as the thesis model.
	const Eigen::Isometry3d T = head.T_CamCvInC0(side, a).inverse(Eigen::Isometry);
	const Eigen::Matrix3d K = head.camera().toTCamera().intrinsicParams.asEigen();
	Eigen::Matrix<double, 3, 4> P;
	P << K * T.linear(), K * T.translation();
	cv::Mat out;
	cv::eigen2cv(P, out);
	return out;
}

const Scene& scene()
{
	static const Scene s = []
	{
		Scene sc;
		std::mt19937 rng(42);
		std::uniform_real_distribution<double> lat(-0.8, 0.8), up(-0.6, 0.4), fwd(1, 5);
		std::normal_distribution<double> noise(0, 0.5);
		sc.px_left.create(2, kPoints, CV_64F);
		sc.px_right.create(2, kPoints, CV_64F);
		for (int i = 0; i < kPoints; ++i)
		{
			sc.points.emplace_back(lat(rng), up(rng), fwd(rng));
			Eigen::Vector4d px = sc.head.project(sc.points.back(), sc.angles).asVector();
			for (int k = 0; k < 4; ++k) px[k] += noise(rng);
			sc.pixels.push_back(StereoPixels::fromVector(px));
			sc.px_left.at<double>(0, i) = px[0];
			sc.px_left.at<double>(1, i) = px[1];
			sc.px_right.at<double>(0, i) = px[2];
			sc.px_right.at<double>(1, i) = px[3];
		}
		sc.P_left = projectionMatrix(sc.head, Side::Left, sc.angles);
		sc.P_right = projectionMatrix(sc.head, Side::Right, sc.angles);
		return sc;
	}();
	return s;
}

void BM_ProjectWithJacobian(benchmark::State& state)
{
	const Scene& s = scene();
	Eigen::Matrix<double, 4, 3> J;
	size_t i = 0;
	for (auto _ : state)
		benchmark::DoNotOptimize(s.head.project(s.points[i++ % kPoints], s.angles, &J));
	state.SetItemsProcessed(state.iterations());
}

void BM_Fixate(benchmark::State& state)
{
	const Scene& s = scene();
	size_t i = 0;
	for (auto _ : state) benchmark::DoNotOptimize(s.head.fixate(s.points[i++ % kPoints]));
	state.SetItemsProcessed(state.iterations());
}

void BM_TriangulateWithCovariance(benchmark::State& state)
{
	const Scene& s = scene();
	size_t i = 0;
	for (auto _ : state)
		benchmark::DoNotOptimize(s.head.triangulate(s.pixels[i++ % kPoints], s.angles, 0.5));
	state.SetItemsProcessed(state.iterations());
}

// The pair compared: kPoints triangulations per iteration, ours point by point, OpenCV batched.
void BM_TriangulateMidpoint_Batch(benchmark::State& state)
{
	const Scene& s = scene();
	for (auto _ : state)
		for (const StereoPixels& px : s.pixels)
			benchmark::DoNotOptimize(s.head.triangulatePoint(px, s.angles));
	state.SetItemsProcessed(state.iterations() * kPoints);
}

void BM_OpenCvTriangulatePoints_Batch(benchmark::State& state)
{
	const Scene& s = scene();
	cv::Mat X;
	for (auto _ : state)
	{
		cv::triangulatePoints(s.P_left, s.P_right, s.px_left, s.px_right, X);
		benchmark::DoNotOptimize(X.data);
	}
	state.SetItemsProcessed(state.iterations() * kPoints);
}

BENCHMARK(BM_ProjectWithJacobian);
BENCHMARK(BM_Fixate);
BENCHMARK(BM_TriangulateWithCovariance);
BENCHMARK(BM_TriangulateMidpoint_Batch);
BENCHMARK(BM_OpenCvTriangulatePoints_Batch);

// Console output plus the per-point time of both triangulations and their ratio.
class RatioReporter : public benchmark::ConsoleReporter
{
 public:
	void ReportRuns(const std::vector<Run>& runs) override
	{
		ConsoleReporter::ReportRuns(runs);
		for (const Run& r : runs) ns_per_iter_[r.benchmark_name()] = r.GetAdjustedCPUTime();
	}
	void Finalize() override
	{
		ConsoleReporter::Finalize();
		const auto ours = ns_per_iter_.find("BM_TriangulateMidpoint_Batch");
		const auto cv = ns_per_iter_.find("BM_OpenCvTriangulatePoints_Batch");
		if (ours == ns_per_iter_.end() || cv == ns_per_iter_.end()) return;
		std::printf(
		    "summary: CPU time per point: midpoint (eqs 4.45-4.50) %.1f ns, OpenCV "
		    "cv::triangulatePoints %.1f ns; CPU-time ratio midpoint/OpenCV = %.2f\n",
		    ours->second / kPoints, cv->second / kPoints, ours->second / cv->second);
	}

 private:
	std::map<std::string, double> ns_per_iter_;
};

// How far the two triangulations are from the true points on the same noisy data.
void printAccuracy()
{
	const Scene& s = scene();
	cv::Mat X;
	cv::triangulatePoints(s.P_left, s.P_right, s.px_left, s.px_right, X);
	double ours = 0, theirs = 0, between = 0;
	for (int i = 0; i < kPoints; ++i)
	{
		const Eigen::Vector3d m = s.head.triangulatePoint(s.pixels[i], s.angles);
		const Eigen::Vector3d c(X.at<double>(0, i) / X.at<double>(3, i),
		                        X.at<double>(1, i) / X.at<double>(3, i),
		                        X.at<double>(2, i) / X.at<double>(3, i));
		ours += (m - s.points[i]).norm() / kPoints;
		theirs += (c - s.points[i]).norm() / kPoints;
		between += (m - c).norm() / kPoints;
	}
	std::printf(
	    "summary: mean 3D error with 0.5 px noise, %d points 1-5 m: midpoint %.4f m, OpenCV %.4f "
	    "m, "
	    "between them %.4f m\n",
	    kPoints, ours, theirs, between);
}
}  // namespace

int main(int argc, char** argv)
{
	benchmark::Initialize(&argc, argv);
	if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
	RatioReporter reporter;
	benchmark::RunSpecifiedBenchmarks(&reporter);
	printAccuracy();
	benchmark::Shutdown();
	return 0;
}
