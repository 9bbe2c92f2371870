#pragma once
// mrolr-mission's summary lines and progress line, shared by a run and a replay.
#include <mrolr/mission/Mission.h>

#include <nlohmann/json.hpp>

#include <ostream>
#include <string>

namespace mrolr::apps::summary
{
using nlohmann::json;

/** @p v with @p precision decimals, "n/a" when it is not a number. */
std::string num(const json& v, int precision = 3);
/** The run's summary lines from its report. */
void printSummary(std::ostream& out, const json& r, const std::string& dir);
/** Progress on @p progress while @p m runs: on a terminal one line rewritten in place (carriage
 * returns); to a file or a pipe plain lines, one at each new stage and one a minute of mission
 * time, so a log stays readable. */
void attachProgress(mission::Mission& m, std::ostream& progress);

}  // namespace mrolr::apps::summary
