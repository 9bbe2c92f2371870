#include "RatioReporter.h"

#include <cmath>
#include <cstdio>
#include <ostream>
#include <set>

namespace mrolr::bench
{
namespace
{
std::string cell(double v, const char* fmt)
{
	if (!std::isfinite(v)) return "-";
	char buf[32];
	std::snprintf(buf, sizeof buf, fmt, v);
	return buf;
}
}  // namespace

void RatioReporter::ReportRuns(const std::vector<Run>& runs)
{
	benchmark::ConsoleReporter::ReportRuns(runs);
	for (const Run& r : runs)
	{
		if (r.error_occurred || r.run_type != Run::RT_Iteration || r.iterations == 0) continue;
		const auto n = r.counters.find("N");
		if (n == r.counters.end()) continue;
		times_[r.run_name.function_name][static_cast<int>(n->second.value)] =
		    r.cpu_accumulated_time / static_cast<double>(r.iterations);
	}
}

double RatioReporter::lookup(const std::string& name, int N) const
{
	const auto f = times_.find(name);
	if (f == times_.end()) return NAN;
	const auto t = f->second.find(N);
	return t == f->second.end() ? NAN : t->second;
}

void RatioReporter::printTable(std::ostream& out) const
{
	std::set<int> Ns;
	for (const auto& f : times_)
		for (const auto& t : f.second) Ns.insert(t.first);
	out << "\nOne measurement update (prediction + 3-D measurement of one feature), CPU time\n"
	    << "(CPU rather than wall time: the machine may be shared with other jobs):\n"
	    << "|    N | MRPT naive ms | MRPT AlaDavison ms | postponed step us | step+catch-up ms"
	    << " | step/naive | step/AlaDavison | (step+catch-up)/naive | (step+catch-up)/AlaDavison "
	       "|\n"
	    << "|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
	for (int N : Ns)
	{
		const double nv = lookup("BM_MrptNaive", N), ad = lookup("BM_MrptAlaDavison", N);
		const double st = lookup("BM_PostponedStep", N),
		             cu = lookup("BM_PostponedStepAndCatchUp", N);
		out << "| " << N << " | " << cell(nv * 1e3, "%.3f") << " | " << cell(ad * 1e3, "%.3f")
		    << " | " << cell(st * 1e6, "%.2f") << " | " << cell(cu * 1e3, "%.3f") << " | "
		    << cell(st / nv, "%.2e") << " | " << cell(st / ad, "%.2e") << " | "
		    << cell(cu / nv, "%.3f") << " | " << cell(cu / ad, "%.3f") << " |\n";
	}
}

}  // namespace mrolr::bench
