// bench_vision: the vision-SLAM measurement cycle on 640x480 images with per-stage times, and NSSD
// search by OpenCV's matchTemplate against the literal eq 5.21, measured in the same run with the
// ratio printed at the end. Image capture (rendering) is excluded from the cycle time.
#include <mrolr/geometry/BiSightOptions.h>
#include <mrolr/vision/PatchSearch.h>
#include <mrolr/vision/ShiTomasi.h>
#include <mrolr/vision/SyntheticWorld.h>
#include <mrolr/vision/VisualSlam.h>
#include <mrolr/world/World.h>

#include <mrpt/config/CConfigFile.h>

#include <benchmark/benchmark.h>
#include <opencv2/core.hpp>

#include <iostream>
#include <map>

using namespace mrolr;

namespace
{
const std::string kRoot = MROLR_SOURCE_DIR;

geometry::BiSightHead configuredHead()
{
	return geometry::BiSightHead(geometry::BiSightOptions::fromFile(kRoot + "/config/bisight.ini"));
}

/** A 640x480 synthetic pair showing one textured point at the image centre, and a 3-sigma ellipse
 * of 40 x 25 px half-axes around it (a typical search region while tracking). */
struct EllipseProblem
{
	cv::Mat image, patch;
	vision::ImageEllipse ellipse;
	EllipseProblem()
	{
		const auto head = configuredHead();
		vision::SyntheticStereoHead device(head, 2.0, 3);
		const Eigen::Vector3d p(0.2, 0.3, 3.0);
		device.setPoints({{p, vision::makeTexture(31, 8)}});
		device.moveTo(head.fixate(p));
		image = device.grab().left;
		patch = vision::extractPatch(image, {320, 240}, 13);
		ellipse.centre = {324, 237};
		ellipse.cov = Eigen::Vector2d(40.0 * 40 / 9, 25.0 * 25 / 9).asDiagonal();
	}
};

void nssdSearch(benchmark::State& state, vision::NssdMethod method)
{
	const EllipseProblem pb;
	for (auto _ : state)
		benchmark::DoNotOptimize(
		    vision::searchEllipse(pb.image, pb.patch, pb.ellipse, 0.9, method));
	state.counters["ellipse_area_px2"] = pb.ellipse.area();
}
void BM_NssdSearch_OpenCvMatchTemplate(benchmark::State& s)
{
	nssdSearch(s, vision::NssdMethod::OpenCv);
}
void BM_NssdSearch_OwnEq5_21(benchmark::State& s)
{
	nssdSearch(s, vision::NssdMethod::Direct);
}
BENCHMARK(BM_NssdSearch_OpenCvMatchTemplate)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_NssdSearch_OwnEq5_21)->Unit(benchmark::kMicrosecond);

std::vector<vision::TexturedLandmark> labLandmarks()
{
	const auto w = world::World::load(kRoot + "/maps/lab/world.ini");
	std::vector<vision::TexturedLandmark> out;
	for (size_t i = 0; i < w.landmarks.size(); ++i)
		out.push_back(
		    {w.landmarks[i].name, w.landmarks[i].p_LinW, vision::makeTexture(31, 1000 + i)});
	return out;
}

slam::SlamOptions slamOptions()
{
	mrpt::config::CConfigFile cfg(kRoot + "/config/slam.ini"),
	    bisight(kRoot + "/config/bisight.ini");
	slam::SlamOptions o;
	o.loadFromConfigFile(cfg, "slam");
	o.head.loadFromConfigFile(bisight, "bisight");
	return o;
}

/** The cycle with the robot shuttling 20 cm forward and back in the lab; manual time = the robot's
 * processing (predict + select + search + match + update), without image capture or acquisition. */
void BM_MeasurementCycle(benchmark::State& state)
{
	const auto head = configuredHead();
	const base::LabmateModel model;
	slam::ActiveSlamFilter filter(slamOptions(), model);
	filter.reset();
	vision::SyntheticWorld device(head, labLandmarks(), 2.0, 5);
	vision::VisualSlam vslam(filter, head,
	                         vision::VisionOptions::fromFile(kRoot + "/config/slam.ini"), model);
	vslam.step({}, device);
	vision::CycleTimes sum;
	int k = 0, measured = 0;
	Eigen::Vector3d x_true = Eigen::Vector3d::Zero();
	for (auto _ : state)
	{
		const auto u = model.translationControl(k++ % 2 ? -0.2 : 0.2);
		x_true = model.move(x_true, u);
		device.setVehicle(x_true);
		const vision::CycleRecord r = vslam.step(u, device);
		measured += r.measurement.found;
		sum += r.times;
		state.SetIterationTime(r.times.processingMs() / 1000);
	}
	const double n = std::max(k, 1);
	for (auto [name, v] : std::map<std::string, double>{{"predict_ms", sum.predict_ms},
	                                                    {"select_ms", sum.select_ms},
	                                                    {"search_ms", sum.search_ms},
	                                                    {"match_ms", sum.match_ms},
	                                                    {"update_ms", sum.update_ms},
	                                                    {"grab_ms_excluded", sum.grab_ms}})
		state.counters[name] = v / n;
	state.counters["cycles_per_s"] = 1000.0 * n / std::max(sum.processingMs(), 1e-9);
	state.counters["found_fraction"] = measured / n;
}
BENCHMARK(BM_MeasurementCycle)->UseManualTime()->Unit(benchmark::kMillisecond)->MinTime(2.0);

/** Console output plus the matchTemplate / own-NSSD ratio and the cycle rate at the end. */
class VisionReporter : public benchmark::ConsoleReporter
{
 public:
	void ReportRuns(const std::vector<Run>& runs) override
	{
		benchmark::ConsoleReporter::ReportRuns(runs);
		for (const auto& r : runs)
		{
			if (r.error_occurred || r.iterations == 0) continue;
			times_[r.benchmark_name()] = r.GetAdjustedRealTime();
			if (r.counters.count("cycles_per_s")) cycles_per_s_ = r.counters.at("cycles_per_s");
		}
	}
	void summary(std::ostream& out) const
	{
		const auto a = times_.find("BM_NssdSearch_OwnEq5_21");
		const auto b = times_.find("BM_NssdSearch_OpenCvMatchTemplate");
		if (a != times_.end() && b != times_.end())
			out << "NSSD search, own eq 5.21 / OpenCV matchTemplate time ratio: "
			    << a->second / b->second << "\n";
		if (cycles_per_s_ > 0)
			out << "measurement cycle: " << cycles_per_s_
			    << " cycles/s on one core (target >= 100)\n";
	}

 private:
	std::map<std::string, double> times_;
	double cycles_per_s_ = 0;
};
}  // namespace

int main(int argc, char** argv)
{
	benchmark::Initialize(&argc, argv);
	if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 2;
	cv::setNumThreads(1);  // the target is stated for one core
	VisionReporter reporter;
	benchmark::RunSpecifiedBenchmarks(&reporter);
	reporter.summary(std::cout);
	benchmark::Shutdown();
	return 0;
}
