#pragma once
/** Joint values of the UMI RTX (thesis B.3.1): the column height d1 and the angles q1..q6. */

#include <Eigen/Core>

#include <array>

namespace mrolr::arm
{
/** One configuration of the arm: d1 in mm, q1..q6 in radians (DH θ of links 1..6, B.3.1). */
struct RtxJoints
{
	double d1_mm = 922;
	std::array<double, 6> q_rad = {0, 0, 0, 0, 1.5707963267948966, 0};  ///< q1..q6

	/** From d1 in mm and q1..q6 in degrees (the command-line units). */
	static RtxJoints fromMmDeg(const std::array<double, 7>& d1_mm_q_deg);
	/** [d1_mm, q1_deg, ..., q6_deg]. */
	std::array<double, 7> toMmDeg() const;

	/** The six variables the solvers move: [d1_mm, q2, q3, q4, q5, q6] (q1 stays fixed). */
	Eigen::Matrix<double, 6, 1> active() const;
	void setActive(const Eigen::Matrix<double, 6, 1>& v);

	double q(int i) const { return q_rad[static_cast<size_t>(i - 1)]; }  ///< q_i, i = 1..6
};

}  // namespace mrolr::arm
