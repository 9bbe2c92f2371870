#pragma once
// A console reporter that also keeps the CPU time per iteration of every benchmark by family and
// N (the "N" counter), and prints the comparison table of the update methods at the end.

#include <benchmark/benchmark.h>

#include <iosfwd>
#include <map>
#include <string>

namespace mrolr::bench
{
class RatioReporter : public benchmark::ConsoleReporter
{
 public:
	void ReportRuns(const std::vector<Run>& runs) override;

	/** CPU seconds per iteration, by benchmark function name and N. */
	const std::map<std::string, std::map<int, double>>& times() const { return times_; }

	/** The table: per N the time of each method and the ratios of the postponed step (and step
	 * plus catch-up) to MRPT's naive and scalar-at-once updates. Missing entries print as "-". */
	void printTable(std::ostream& out) const;

 private:
	double lookup(const std::string& name, int N) const;

	std::map<std::string, std::map<int, double>> times_;
};

}  // namespace mrolr::bench
