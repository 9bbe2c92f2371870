// InnerBalls: balls inside SelfOcclusion's polytope, a quick proof that a sight line crosses it.
// Each ball lies inside every face by the margin, and throughBall is the segment's distance to a
// centre against its radius.
#include <mrolr/recog/InnerBalls.h>
#include <mrolr/recog/SelfOcclusion.h>
#include <mrolr/sim/SyntheticObjects.h>

#include <gtest/gtest.h>

#include <random>

using namespace mrolr::recog;

namespace
{
/** A k-DOP of 100 directions about @p pts, shrunk by 3 mm, as SelfOcclusion builds it. */
std::vector<double> offsetsAbout(const std::vector<Eigen::Vector3d>& normals,
                                 const std::vector<Eigen::Vector3d>& pts)
{
	std::vector<double> d;
	for (const auto& n : normals)
	{
		double m = -1e300;
		for (const auto& p : pts) m = std::max(m, n.dot(p));
		d.push_back(m - 3);
	}
	return d;
}

std::vector<Eigen::Vector3d> pointsOf(const mrolr::model::WireFrame& wf)
{
	std::vector<Eigen::Vector3d> pts;
	for (const auto& f : featuresOf(wf))
		for (const auto& p : samplesOf(f, 8)) pts.push_back(p);
	return pts;
}

/** The distance of the segment from @p a to @p b to @p c, by dense steps along it. */
double segmentDistance(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c)
{
	double best = 1e300;
	for (int k = 0; k <= 20000; ++k)
		best = std::min(best, (a + (b - a) * (k / 20000.0) - c).norm());
	return best;
}
}  // namespace

TEST(InnerBalls, EveryBallLiesInsideEveryFaceByTheMargin)
{
	const auto normals = sphereDirections(100);
	for (const auto& wf : mrolr::sim::makeLabObjects())
	{
		const auto pts = pointsOf(wf);
		const auto offsets = offsetsAbout(normals, pts);
		const InnerBalls balls = innerBalls(normals, offsets, pts, 0.5);
		ASSERT_GE(balls.n, 1u) << wf.name;  // every lab object has room for a 1 mm ball
		for (size_t b = 0; b < InnerBalls::kMax; ++b)
		{
			if (b >= balls.n)
			{
				EXPECT_LT(balls.r2[b], 0) << wf.name;  // unused: nothing passes through
				continue;
			}
			const Eigen::Vector3d c(balls.x[b], balls.y[b], balls.z[b]);
			const double r = std::sqrt(balls.r2[b]);
			EXPECT_GE(r, 1) << wf.name;
			for (size_t i = 0; i < normals.size(); ++i)
				EXPECT_LE(normals[i].dot(c) + r, offsets[i] - 0.5 + 1e-9) << wf.name << " " << b;
		}
	}
}

// Random segments from cameras 300 to 900 mm away to points near the object, against the
// distance to each centre found by dense steps (segments within 0.05 mm of a sphere left out).
TEST(InnerBalls, ThroughBallIsTheSegmentsDistanceToACentreWithinItsRadius)
{
	std::mt19937 rng(3);
	std::uniform_real_distribution<double> u(-1, 1);
	const auto normals = sphereDirections(100);
	const auto cube = mrolr::sim::makeAlphabetCube();
	const auto pts = pointsOf(cube);
	const InnerBalls balls = innerBalls(normals, offsetsAbout(normals, pts), pts);
	ASSERT_GE(balls.n, 1u);
	int through = 0, missed = 0;
	for (int trial = 0; trial < 400; ++trial)
	{
		const Eigen::Vector3d c_O =
		    Eigen::Vector3d(u(rng), u(rng), u(rng)).normalized() * (600 + 300 * u(rng));
		const Eigen::Vector3d p_O = Eigen::Vector3d(u(rng), u(rng), u(rng)) * 60;
		bool expected = false, borderline = false;
		for (size_t b = 0; b < balls.n; ++b)
		{
			const double d = segmentDistance(c_O, p_O, {balls.x[b], balls.y[b], balls.z[b]});
			const double r = std::sqrt(balls.r2[b]);
			expected = expected || d < r;
			borderline = borderline || std::abs(d - r) < 0.05;
		}
		if (borderline) continue;
		EXPECT_EQ(throughBall(ballsSeenFrom(balls, c_O), p_O - c_O), expected) << trial;
		(expected ? through : missed) += 1;
	}
	EXPECT_GT(through, 50);
	EXPECT_GT(missed, 50);
}

// A point's own ball (ownBall): inside every face by the margin, like the inner balls, and found
// for most of a model's samples (the lab objects' samples, 8 per feature).
TEST(InnerBalls, APointsOwnBallLiesInsideEveryFaceByTheMargin)
{
	const auto normals = sphereDirections(100);
	for (const auto& wf : mrolr::sim::makeLabObjects())
	{
		const auto pts = pointsOf(wf);
		const auto offsets = offsetsAbout(normals, pts);
		const InnerBalls balls = innerBalls(normals, offsets, pts);
		size_t with_ball = 0;
		for (const auto& p : pts)
		{
			const OwnBall b = ownBall(normals, offsets, balls, p, 0.5);
			if (b.r2 < 0) continue;
			++with_ball;
			const Eigen::Vector3d c(b.x, b.y, b.z);
			const double r = std::sqrt(b.r2);
			EXPECT_GE(r, 0.5) << wf.name;
			for (size_t i = 0; i < normals.size(); ++i)
				ASSERT_LE(normals[i].dot(c) + r, offsets[i] - 0.5 + 1e-9) << wf.name << " " << i;
		}
		EXPECT_GT(with_ball, pts.size() / 2) << wf.name;
	}
}
