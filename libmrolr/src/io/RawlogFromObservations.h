#pragma once
// An observations-only rawlog (ObservationLog.h) read as RawlogRecords (private to io).
#include <mrolr/io/ObservationLog.h>
#include <mrolr/io/Rawlog.h>

#include <string>
#include <vector>

namespace mrolr::io
{
/** One record per odometry reading and one per grabbed pair (`BISIGHT` then its `HEAD_GRAB`),
 * each carrying the latest odometry, head angles and truth (`GROUND_TRUTH`, the world side's,
 * when the recording has it: the base stands still between steps);
 * @p path locates the external images. */
std::vector<RawlogRecord> recordsOf(const ObservationLog& log, const std::string& path,
                                    ImageLoading images = ImageLoading::Load);

}  // namespace mrolr::io
