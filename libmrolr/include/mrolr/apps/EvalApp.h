#pragma once
/** `mrolr-eval`: checks a run's report against the world's truth after the run, for runs whose
 * robot had no simulator in its process (docs/mission.md "Two processes"):
 *
 *     mrolr-eval --report out/X/report.json --truth T.json [--out R.json] [--json]
 *
 * T.json is what `mrolr-serial emulate --truth-out` writes. The report gets its truth fields and
 * its `eval` object (eval/MissionEval.h) and is written back (or to --out), with report.md next
 * to it. Prints a summary (or the report with --json). Exit 0 when eval confirms the robot's
 * success, 3 when not, 1 for an unreadable or malformed file (named), 2 for bad arguments. */
#include <nlohmann/json.hpp>

#include <iosfwd>
#include <string>
#include <vector>

namespace mrolr::apps
{
class EvalApp
{
 public:
	void initialize(const std::vector<std::string>& args);
	int run(std::ostream& out);

	std::string report_path, truth_path, out_path;
	bool json = false, help_shown = false;
	nlohmann::json report;  ///< after evaluation
};

}  // namespace mrolr::apps
