// Horizontal circles (stereo/HorizontalCircles.h): a rim seen nearly edge-on (image semi-minor axis
// 3-5 px) is fixed by its left image arc and one depth once the up direction is known; a circle
// that is not horizontal is refused.
#include "SyntheticStereo.h"

#include <mrolr/stereo/HorizontalCircles.h>
#include <mrolr/stereo/SceneReconstruction.h>

#include <gtest/gtest.h>

#include <optional>

using namespace mrolr::stereo;
using namespace mrolr::stereo::test;

namespace
{
const Eigen::Vector3d kUp(0, 1, 0);           // the test rig looks horizontally: L's y is up
const Eigen::Vector3d kCentre(30, -90, 800);  // thesis L (mm): 6.4° below the optic axis
const double kRadius = 40;                    // image semi-axes about 35 and 3.9 px

/** A circle of radius kRadius about kCentre in the plane of unit axes u, v. */
Eigen::Vector3d circlePoint(const Eigen::Vector3d& u, const Eigen::Vector3d& v, double t)
{
	return kCentre + kRadius * (std::cos(t) * u + std::sin(t) * v);
}

/** The projected front half of the circle (rectified left px, in order) and stereo samples at its
 * two ends (where it crosses the scanlines). */
void frontArc(const Rectifier& rect, const Eigen::Vector3d& u, const Eigen::Vector3d& v,
              std::vector<cv::Point2d>& px, std::vector<StereoEdgel>& depth)
{
	for (int k = 0; k <= 120; ++k)
	{
		const Eigen::Vector3d p = circlePoint(u, v, -M_PI * k / 120);  // z - r sin t: the near half
		px.push_back(rect.leftPixelOf(p));
		if (k < 6 || k > 114) depth.push_back({px.back(), 0, p});
	}
}

/** The reconstructed conic nearest kCentre, if any. */
std::optional<ConicFit3> nearest(const StereoScene& s)
{
	std::optional<ConicFit3> best;
	for (const auto& c : s.conics)
		if (!best || (c.centre - kCentre).norm() < (best->centre - kCentre).norm()) best = c;
	return best;
}

bool recovered(const std::optional<ConicFit3>& c)
{
	return c && (c->centre - kCentre).norm() < 3 && std::abs(c->a - kRadius) < 2 &&
	       std::abs(c->b - kRadius) < 2;
}
}  // namespace

TEST(HorizontalCircles, ProjectedEdgeOnRimGivesItsCircle)
{
	const Rectifier rect(testRig());
	std::vector<cv::Point2d> px;
	std::vector<StereoEdgel> depth;
	frontArc(rect, {1, 0, 0}, {0, 0, 1}, px, depth);
	double top = 1e9, bottom = -1e9;
	for (const auto& q : px) top = std::min(top, q.y), bottom = std::max(bottom, q.y);
	EXPECT_GT(bottom - top, 2.5);  // the half ellipse's height is its semi-minor axis: 3-5 px
	EXPECT_LT(bottom - top, 5.0);
	const auto c = horizontalCircle(px, depth, std::nullopt, kUp, rect, HorizontalCircleOptions{});
	ASSERT_TRUE(c.has_value());
	EXPECT_LT((c->centre - kCentre).norm(), 1.0);
	EXPECT_NEAR(c->a, kRadius, 0.5);
	EXPECT_GT(std::abs(c->normal.dot(kUp)), 0.9999);
	EXPECT_GT(c->t2 - c->t1, 0.95 * M_PI);
	for (double t : {c->t1, 0.5 * (c->t1 + c->t2), c->t2})  // the arc is the near half
		EXPECT_LT(c->pointAt(t).z(), kCentre.z() + 1);
}

TEST(HorizontalCircles, TiltedCircleIsRefused)
{
	const Rectifier rect(testRig());
	for (const auto& [u, v] :
	     {std::pair(Eigen::Vector3d(1, 0, 0),  // pitched 10° towards the camera
	                Eigen::Vector3d(0, std::sin(0.175), std::cos(0.175))),
	      std::pair(Eigen::Vector3d(std::cos(0.26), std::sin(0.26), 0),  // rolled 15°
	                Eigen::Vector3d(0, 0, 1))})
	{
		std::vector<cv::Point2d> px;
		std::vector<StereoEdgel> depth;
		frontArc(rect, u, v, px, depth);
		EXPECT_FALSE(horizontalCircle(px, depth, std::nullopt, kUp, rect, {}).has_value());
		// the same arc is a circle for the right up direction (its own normal)
		EXPECT_TRUE(horizontalCircle(px, depth, std::nullopt, u.cross(v), rect, {}).has_value());
	}
}

TEST(HorizontalCircles, AxisRatioOfTheConeCutByThePlane)
{
	const Rectifier rect(testRig());
	std::vector<cv::Point2f> px;
	for (int k = 0; k < 72; ++k)
	{
		const cv::Point2d q =
		    rect.leftPixelOf(circlePoint({1, 0, 0}, {0, 0, 1}, 2 * M_PI * k / 72));
		px.emplace_back(static_cast<float>(q.x), static_cast<float>(q.y));
	}
	const cv::RotatedRect el = cv::fitEllipseDirect(px);
	EXPECT_LT(planeSectionAxisRatio(el, kUp, rect), 1.02);
	const Eigen::Vector3d tilted(0, std::cos(0.175), -std::sin(0.175));
	EXPECT_GT(planeSectionAxisRatio(el, tilted, rect), 1.3);
}

TEST(HorizontalCircles, RenderedEdgeOnRimNeedsTheUpDirection)
{
	const auto rig = testRig();
	const std::vector<Face> faces{rectangle({0, -60, 900}, {1, 0, 0}, {0, 1, 0}, 900, 700, 40),
	                              disc(kCentre, {1, 0, 0}, {0, 0, 1}, kRadius, 200)};
	cv::Mat l, r;
	renderPair(faces, rig, l, r);
	SceneOptions o = stepDefaults();
	o.circles.enabled = true;
	o.circles.max_residual_px = 0.35;  // config/model.ini's value
	const auto with = nearest(reconstructScene(l, r, rig, o, kUp));
	ASSERT_TRUE(with.has_value());
	EXPECT_LT((with->centre - kCentre).norm(), 3.0);
	EXPECT_NEAR(with->a, kRadius, 2.0);
	EXPECT_NEAR(with->b, kRadius, 2.0);
	EXPECT_FALSE(recovered(nearest(reconstructScene(l, r, rig, o))));  // no up direction
	o.circles.enabled = false;
	EXPECT_FALSE(recovered(nearest(reconstructScene(l, r, rig, o, kUp))));  // step off
}
