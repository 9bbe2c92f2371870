#pragma once
// Wall-clock lap timer of the vision cycle's stages (internal to the vision area).
#include <chrono>

namespace mrolr::vision::detail
{
/** Milliseconds since @p t0, and resets t0 to now. */
inline double lap(std::chrono::steady_clock::time_point& t0)
{
	const auto now = std::chrono::steady_clock::now();
	const double ms = std::chrono::duration<double, std::milli>(now - t0).count();
	t0 = now;
	return ms;
}
}  // namespace mrolr::vision::detail
