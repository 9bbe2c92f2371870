#include <mrolr/arm/ArmError.h>
#include <mrolr/arm/MotorCounts.h>

#include <mrpt/core/bits_math.h>

#include <cmath>
#include <sstream>
#include <tuple>

namespace mrolr::arm
{
std::pair<double, double> wristCounts(double q5_rad, double q6_rad, const RtxOptions& o)
{
	const double pitch = 90.0 - mrpt::RAD2DEG(q5_rad);
	const double roll = mrpt::RAD2DEG(q6_rad);
	return {(-pitch + roll) / o.wrist_deg_per_count, (-pitch - roll) / o.wrist_deg_per_count};
}

MotorCounts jointsToCounts(const RtxJoints& j, const RtxOptions& o)
{
	MotorCounts c{};
	c[0] = (j.d1_mm - o.d1_top_mm) / o.column_mm_per_count;
	c[1] = mrpt::RAD2DEG(j.q(2)) / o.shoulder_deg_per_count;
	c[2] = mrpt::RAD2DEG(j.q(3)) / o.elbow_deg_per_count;
	c[3] = mrpt::RAD2DEG(j.q(4)) / o.yaw_deg_per_count;
	std::tie(c[4], c[5]) = wristCounts(j.q(5), j.q(6), o);
	return c;
}

RtxJoints countsToJoints(const MotorCounts& c, const RtxOptions& o)
{
	RtxJoints j;
	j.d1_mm = o.d1_top_mm + c[0] * o.column_mm_per_count;
	j.q_rad[0] = mrpt::DEG2RAD(o.q1_fixed_deg);
	j.q_rad[1] = mrpt::DEG2RAD(c[1] * o.shoulder_deg_per_count);
	j.q_rad[2] = mrpt::DEG2RAD(c[2] * o.elbow_deg_per_count);
	j.q_rad[3] = mrpt::DEG2RAD(c[3] * o.yaw_deg_per_count);
	const double minus_pitch = 0.5 * (c[4] + c[5]) * o.wrist_deg_per_count;
	const double roll = 0.5 * (c[4] - c[5]) * o.wrist_deg_per_count;
	j.q_rad[4] = mrpt::DEG2RAD(90.0 + minus_pitch);
	j.q_rad[5] = mrpt::DEG2RAD(roll);
	return j;
}

std::array<long, kMotorCount> roundCounts(const MotorCounts& c)
{
	std::array<long, kMotorCount> r{};
	for (size_t i = 0; i < c.size(); ++i) r[i] = std::lround(c[i]);
	return r;
}

int firstViolatedMotor(const MotorCounts& c, const RtxOptions& o)
{
	constexpr double tol = 1e-9;
	for (int i = 0; i < kMotorCount; ++i)
	{
		const auto& r = o.limits[i];
		const double v = c[static_cast<size_t>(i)];
		if (!(v >= r.min - tol && v <= r.max + tol)) return i;
	}
	return -1;
}

std::string describeViolation(Motor m, double count, const CountRange& limit)
{
	std::ostringstream s;
	s << motorName(m) << " count " << count << " outside limit [" << limit.min << ", "
	  << limit.max << "]";
	return s.str();
}

std::string limitViolation(const MotorCounts& c, const RtxOptions& o)
{
	const int i = firstViolatedMotor(c, o);
	if (i < 0) return {};
	return describeViolation(static_cast<Motor>(i), c[static_cast<size_t>(i)], o.limits[i]);
}

void requireWithinLimits(const RtxJoints& j, const RtxOptions& o)
{
	const std::string v = limitViolation(jointsToCounts(j, o), o);
	if (!v.empty()) throw UnreachableError(v);
}

}  // namespace mrolr::arm
