#pragma once
// An observations-only rawlog (ObservationLog.h) read as RawlogRecords (private to io).
#include <mrolr/io/ObservationLog.h>
#include <mrolr/io/Rawlog.h>

#include <string>
#include <vector>

namespace mrolr::io
{
/** One record per odometry reading (with the truth written before it, if any) and one per
 * grabbed pair (`BISIGHT` then its `HEAD_GRAB`), carrying the latest odometry and head angles;
 * @p path locates the external images. */
std::vector<RawlogRecord> recordsOf(const ObservationLog& log, const std::string& path);

}  // namespace mrolr::io
