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

/** The test of one ball, without a branch: with o its centre and d the point, both from the
 * camera (od = o·d, oo = |o|², dd = |d|²), the point inside the ball (|o − d|² <= r²), or the
 * segment's point nearest the centre (0 < t < 1) inside it. */
inline bool segmentMeetsBall(double od, double oo, double dd, double r2)
{
	const bool end = oo - 2 * od + dd <= r2;
	const bool between = (od > 0) & (od < dd) & (oo * dd - od * od <= r2 * dd);
	return end | between;
}

/** A point's own ball inside the polytope (SelfOcclusion::PointSight): near the point, so that a
 * sight line that reaches the point through the object's inside, as it does to most hidden points,
 * passes through it, where it misses the inner balls about the middle (on the bench sweep it proved
 * 2.4 of the 3.5 million hidden samples the inner balls missed). */
struct OwnBall
{
	double x = 0, y = 0, z = 0;  ///< centre
	double r2 = -1;              ///< squared radius; -1: none (nothing passes through)
};

/** The ball inside the polytope of unit @p normals and @p offsets, at least @p margin_mm inside
 * every face, seen from the point @p p_O under the widest angle (radius over distance) among
 * centres on the way from @p p_O to the largest of @p balls (sixteenths of the way) and along the
 * inward normal of the faces within 1 mm of @p p_O (0.5 mm to 128 mm, by √2). None when no such
 * ball has a radius of 0.5 mm. */
OwnBall ownBall(const std::vector<Eigen::Vector3d>& normals, const std::vector<double>& offsets,
                const InnerBalls& balls, const Eigen::Vector3d& p_O, double margin_mm = 0.01);

/** True when the segment from the camera at @p c_O to @p p_O passes through @p b
 * (segmentMeetsBall). */
inline bool throughOwnBall(const OwnBall& b, const Eigen::Vector3d& c_O, const Eigen::Vector3d& p_O)
{
	const double dx = p_O.x() - c_O.x(), dy = p_O.y() - c_O.y(), dz = p_O.z() - c_O.z();
	const double ox = b.x - c_O.x(), oy = b.y - c_O.y(), oz = b.z - c_O.z();
	const double dd = dx * dx + dy * dy + dz * dz, od = ox * dx + oy * dy + oz * dz;
	return segmentMeetsBall(od, ox * ox + oy * oy + oz * oz, dd, b.r2);
}

}  // namespace mrolr::recog
