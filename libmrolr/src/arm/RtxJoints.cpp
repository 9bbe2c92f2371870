#include <mrolr/arm/RtxJoints.h>

#include <mrpt/core/bits_math.h>

namespace mrolr::arm
{
RtxJoints RtxJoints::fromMmDeg(const std::array<double, 7>& v)
{
	RtxJoints j;
	j.d1_mm = v[0];
	for (size_t i = 0; i < 6; ++i) j.q_rad[i] = mrpt::DEG2RAD(v[i + 1]);
	return j;
}

std::array<double, 7> RtxJoints::toMmDeg() const
{
	std::array<double, 7> v{d1_mm};
	for (size_t i = 0; i < 6; ++i) v[i + 1] = mrpt::RAD2DEG(q_rad[i]);
	return v;
}

Eigen::Matrix<double, 6, 1> RtxJoints::active() const
{
	Eigen::Matrix<double, 6, 1> v;
	v << d1_mm, q_rad[1], q_rad[2], q_rad[3], q_rad[4], q_rad[5];
	return v;
}

void RtxJoints::setActive(const Eigen::Matrix<double, 6, 1>& v)
{
	d1_mm = v[0];
	for (size_t i = 1; i < 6; ++i) q_rad[i] = v[static_cast<Eigen::Index>(i)];
}

}  // namespace mrolr::arm
