#pragma once
/** Balls inside a convex polytope {x : n_i·x <= d_i} (SelfOcclusion's shrunk k-DOP): a segment
 * that passes through one of them crosses the polytope, so a sight line through a ball proves a
 * sample hidden without the clipping against every face (SelfOcclusion::hidden). The balls sit a
 * margin inside the faces, so that the clipping, done apart, can only agree. Model frame, mm. */

#include <Eigen/Core>

#include <array>
#include <cstddef>
#include <vector>

namespace mrolr::recog
{
struct InnerBalls
{
	static constexpr size_t kMax = 8;
	using PerBall = std::array<double, kMax>;
	PerBall x{}, y{}, z{};  ///< centres
	PerBall r2{};           ///< squared radii; -1 for the unused ones (nothing passes through)
	size_t n = 0;
};

/** Up to InnerBalls::kMax large, spread balls inside the polytope of unit @p normals and
 * @p offsets, each at least @p margin_mm inside every face: centres from a grid over the box of
 * @p points (points inside the polytope, e.g. the samples it was built around), the largest ball
 * first, then each next largest whose centre lies outside 0.7 of a chosen one's radius. Balls of
 * radius below 1 mm are not kept. */
InnerBalls innerBalls(const std::vector<Eigen::Vector3d>& normals,
                      const std::vector<double>& offsets,
                      const std::vector<Eigen::Vector3d>& points, double margin_mm = 0.01);

/** The balls as seen from a camera at c_O: their centres relative to it. */
struct BallsSeen
{
	InnerBalls::PerBall ox{}, oy{}, oz{}, r2{};
	InnerBalls::PerBall oo{};    ///< |o|², o a centre from the camera
	bool camera_inside = false;  ///< in one of the balls: every sight line passes through it
};
BallsSeen ballsSeenFrom(const InnerBalls& balls, const Eigen::Vector3d& c_O);

/** True when the segment from the camera to the point at @p d_O from it (d_O = p_O − c_O) passes
 * through one of the balls. */
bool throughBall(const BallsSeen& seen, const Eigen::Vector3d& d_O);

}  // namespace mrolr::recog
