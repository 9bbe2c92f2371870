#pragma once
/** SIGINT and SIGTERM as a stop request: while an object of this class lives, either signal sets
 * a flag the mission checks before its next motion (the base and the arm then stop safely and
 * every output is written) instead of killing the process. The previous handlers come back when
 * it is destroyed. One at a time. */
#include <atomic>

namespace mrolr::apps
{
class StopSignals
{
 public:
	StopSignals();
	~StopSignals();
	StopSignals(const StopSignals&) = delete;
	StopSignals& operator=(const StopSignals&) = delete;
	/** Set by the first SIGINT or SIGTERM. */
	std::atomic<bool>& flag();
	/** The signal that set the flag (SIGINT or SIGTERM), 0 if none. */
	int received() const;
};

}  // namespace mrolr::apps
