#pragma once
// Shared helpers of the arm tests: random joint values within the motor limits, pose distances.

#include <mrolr/arm/MotorCounts.h>
#include <mrolr/arm/RtxOptions.h>

#include <mrpt/config/CConfigFile.h>

#include <Eigen/Geometry>

#include <cmath>
#include <random>
#include <sstream>
#include <string>
#include <utility>

namespace mrolr::arm::test
{
/** Uniform random counts within every motor's limits, as joint values. */
inline RtxJoints randomJoints(std::mt19937& rng, const RtxOptions& o = RtxOptions())
{
	MotorCounts c{};
	for (int i = 0; i < kMotorCount; ++i)
		c[static_cast<size_t>(i)] =
		    std::uniform_real_distribution<double>(o.limits[i].min, o.limits[i].max)(rng);
	return countsToJoints(c, o);
}

/** randomJoints() whose wrist centre is within the wrist-radius limit: a reachable pose. */
inline RtxJoints randomReachableJoints(std::mt19937& rng, const RtxOptions& o = RtxOptions())
{
	for (;;)
	{
		const RtxJoints j = randomJoints(rng, o);
		const double c3 = std::cos(j.q(3));
		const double r2 = o.a2_mm * o.a2_mm + o.a3_mm * o.a3_mm + 2 * o.a2_mm * o.a3_mm * c3;
		if (std::sqrt(r2) <= o.wrist_radius_max_mm) return j;
	}
}

/** The dump() of options @p O loaded from @p section of config/arm_rtx.ini, and of its defaults. */
template <class O>
std::pair<std::string, std::string> shippedAndDefaultDump(const std::string& section)
{
	O loaded;
	loaded.loadFromConfigFile(mrpt::config::CConfigFile(MROLR_SOURCE_DIR "/config/arm_rtx.ini"),
	                          section);
	std::ostringstream a, b;
	loaded.dump(a);
	O().dump(b);
	return {a.str(), b.str()};
}

inline double positionError(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b)
{
	return (a.translation() - b.translation()).norm();
}

inline double rotationError(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b)
{
	return Eigen::AngleAxisd(a.linear() * b.linear().transpose()).angle();
}

}  // namespace mrolr::arm::test
