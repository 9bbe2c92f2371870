// Time per inverse-kinematics solve and success rate on the same random reachable RTX poses:
// the closed-form solver (every solution), Orocos KDL's ChainIkSolverPos_LMA and the damped
// least-squares Jacobian solver of B.3.3, both iterative ones started from the initial
// configuration of B.3.1. The summary prints the time ratio KDL LMA / analytic. CPU time on one
// thread; the analytic solver returns every solution of each pose, none cached between solves.
#include <mrolr/arm/AnalyticIk.h>
#include <mrolr/arm/JacobianIk.h>
#include <mrolr/arm/RtxKdl.h>
#include <mrolr/arm/RtxKinematics.h>

#include <benchmark/benchmark.h>
#include <kdl/chainfksolverpos_recursive.hpp>
#include <kdl/chainiksolverpos_lma.hpp>

#include <cstdio>
#include <map>
#include <random>

using namespace mrolr::arm;

namespace
{
constexpr int kPoses = 1000;
constexpr double kTolMm = 1e-3, kTolRad = 1e-6;  // success: the pose reproduced this closely

/** Random joints within every motor limit whose wrist is within the 507 mm radius, and their T06.
 */
const std::vector<Eigen::Isometry3d>& poses()
{
	static const std::vector<Eigen::Isometry3d> out = []
	{
		std::mt19937 rng(2026);
		const RtxOptions o;
		const RtxKinematics kin(o);
		std::vector<Eigen::Isometry3d> v;
		while (v.size() < kPoses)
		{
			MotorCounts c{};
			for (int i = 0; i < kMotorCount; ++i)
				c[static_cast<size_t>(i)] =
				    std::uniform_real_distribution<double>(o.limits[i].min, o.limits[i].max)(rng);
			const RtxJoints j = countsToJoints(c, o);
			const Eigen::Vector3d pw =
			    kin.T06(j).translation() - o.d6_mm * kin.T06(j).linear().col(2);
			if (std::hypot(pw.x(), pw.y()) <= o.wrist_radius_max_mm) v.push_back(kin.T06(j));
		}
		return v;
	}();
	return out;
}

bool reproduces(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b)
{
	return (a.translation() - b.translation()).norm() < kTolMm &&
	       Eigen::AngleAxisd(a.linear() * b.linear().transpose()).angle() < kTolRad;
}

struct Rates
{
	double reached = 0, within_limits = 0;
};

/** KDL LMA in metres (KDL's scale), from the initial configuration. */
struct Lma
{
	KDL::Chain chain = rtxKdlChain(RtxOptions(), 0, 0.001);
	KDL::ChainIkSolverPos_LMA solver{chain, 1e-12, 500};
	KDL::JntArray seed = toKdl(RtxJoints(), 0.001), out{6};
	int solve(const Eigen::Isometry3d& T) { return solver.CartToJnt(seed, toKdl(T, 0.001), out); }
};

Rates rateAnalytic()
{
	const AnalyticIk ik;
	const RtxKinematics kin;
	Rates r;
	for (const auto& T : poses())
	{
		const auto sols = ik.solve(T).solutions;
		bool ok = !sols.empty();
		for (const auto& s : sols) ok = ok && reproduces(kin.T06(s.joints), T);
		r.reached += ok;
		r.within_limits += ok;  // the analytic solver returns only solutions within the limits
	}
	return {r.reached / kPoses, r.within_limits / kPoses};
}

Rates rateLma()
{
	Lma lma;
	const RtxOptions o;
	const RtxKinematics kin(o);
	Rates r;
	for (const auto& T : poses())
	{
		lma.solve(T);
		const RtxJoints j = fromKdl(lma.out, 0, 0.001);
		const bool ok = reproduces(kin.T06(j), T);
		r.reached += ok;
		RtxJoints wrapped = j;
		for (size_t i = 1; i < 6; ++i) wrapped.q_rad[i] = std::remainder(j.q_rad[i], 2 * M_PI);
		r.within_limits += ok && limitViolation(jointsToCounts(wrapped, o), o).empty();
	}
	return {r.reached / kPoses, r.within_limits / kPoses};
}

Rates rateDls()
{
	const JacobianIk ik;
	const RtxOptions o;
	Rates r;
	for (const auto& T : poses())
	{
		const JacobianIkResult res = ik.solve(T, RtxJoints());
		const bool ok = res.converged;
		r.reached += ok;
		r.within_limits += ok && limitViolation(jointsToCounts(res.joints, o), o).empty();
	}
	return {r.reached / kPoses, r.within_limits / kPoses};
}

void setRates(benchmark::State& state, const Rates& r)
{
	state.counters["success"] = r.reached;
	state.counters["within_limits"] = r.within_limits;
}

void BM_AnalyticIk(benchmark::State& state)
{
	const AnalyticIk ik;
	size_t k = 0;
	for (auto _ : state) benchmark::DoNotOptimize(ik.solve(poses()[k++ % kPoses]));
	state.SetItemsProcessed(state.iterations());
	setRates(state, rateAnalytic());
}
BENCHMARK(BM_AnalyticIk);

void BM_KdlLma(benchmark::State& state)
{
	Lma lma;
	size_t k = 0;
	for (auto _ : state) benchmark::DoNotOptimize(lma.solve(poses()[k++ % kPoses]));
	state.SetItemsProcessed(state.iterations());
	setRates(state, rateLma());
}
BENCHMARK(BM_KdlLma);

void BM_JacobianDls(benchmark::State& state)
{
	const JacobianIk ik;
	size_t k = 0;
	for (auto _ : state) benchmark::DoNotOptimize(ik.solve(poses()[k++ % kPoses], RtxJoints()));
	state.SetItemsProcessed(state.iterations());
	setRates(state, rateDls());
}
BENCHMARK(BM_JacobianDls);

/** Console output plus the per-solve times, success rates and the ratio to the analytic solver. */
class IkRatioReporter : public benchmark::ConsoleReporter
{
 public:
	void ReportRuns(const std::vector<Run>& runs) override
	{
		ConsoleReporter::ReportRuns(runs);
		for (const Run& r : runs)
		{
			auto& e = entries_[r.benchmark_name()];
			e.us = r.GetAdjustedCPUTime() * 1e6 / benchmark::GetTimeUnitMultiplier(r.time_unit);
			e.success = r.counters.at("success");
			e.limits = r.counters.at("within_limits");
		}
	}
	void Finalize() override
	{
		ConsoleReporter::Finalize();
		const double base = entries_.count("BM_AnalyticIk") ? entries_["BM_AnalyticIk"].us : 0;
		std::printf("\nIK on %d random reachable RTX poses (same poses for every solver):\n",
		            kPoses);
		for (const auto& [name, e] : entries_)
			std::printf(
			    "  %-16s %9.2f us/solve  success %5.1f %%  within limits %5.1f %%  time ratio "
			    "to analytic %.1f\n",
			    name.c_str(), e.us, 100 * e.success, 100 * e.limits, base > 0 ? e.us / base : 0.0);
		if (base > 0 && entries_.count("BM_KdlLma"))
			std::printf("  KDL LMA / analytic (every solution): %.1fx  (target >= 50x)\n",
			            entries_["BM_KdlLma"].us / base);
	}

 private:
	struct Entry
	{
		double us = 0, success = 0, limits = 0;
	};
	std::map<std::string, Entry> entries_;
};
}  // namespace

int main(int argc, char** argv)
{
	benchmark::Initialize(&argc, argv);
	IkRatioReporter reporter;
	benchmark::RunSpecifiedBenchmarks(&reporter);
	benchmark::Shutdown();
	return 0;
}
