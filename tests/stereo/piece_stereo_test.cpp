// Piece stereo (stereo/SegmentStereo.h): a rim seen obliquely runs along the scanlines at its top
// and bottom, where edgel matching has nothing to hold on to; the pair of image ellipses still
// gives the whole conic (row crossings and epipolar tangencies correspond).
#include "SyntheticStereo.h"

#include <mrolr/stereo/ImagePieces.h>
#include <mrolr/stereo/SceneReconstruction.h>

#include <gtest/gtest.h>

using namespace mrolr::stereo;
using namespace mrolr::stereo::test;

namespace
{
const Eigen::Vector3d kCentre(30, -60, 800);  // thesis L: x left, y up, z forward (mm)
const double kRadius = 40;

/** A light disc seen 35° from edge-on (its plane tilted towards the camera) on a dark ground. */
std::vector<Face> obliqueDisc()
{
	const double tilt = 35 * M_PI / 180;
	const Eigen::Vector3d u(1, 0, 0), v(0, std::sin(tilt), std::cos(tilt));
	return {rectangle({0, -60, 900}, u, {0, 1, 0}, 900, 700, 40),
	        disc(kCentre, u, v, kRadius, 200)};
}

/** The reconstructed conic nearest the disc's centre, if any. */
std::optional<ConicFit3> rim(const SceneOptions& o)
{
	const auto rig = testRig();
	cv::Mat l, r;
	renderPair(obliqueDisc(), rig, l, r);
	const auto scene = reconstructScene(l, r, rig, o);
	std::optional<ConicFit3> best;
	for (const auto& c : scene.conics)
		if (!best || (c.centre - kCentre).norm() < (best->centre - kCentre).norm()) best = c;
	return best;
}
}  // namespace

TEST(PieceStereo, ObliqueRimFromItsTwoImageEllipses)
{
	const auto c = rim(SceneOptions{});
	ASSERT_TRUE(c.has_value());
	EXPECT_LT((c->centre - kCentre).norm(), 3.0);
	EXPECT_NEAR(c->a, kRadius, 1.5);
	EXPECT_NEAR(c->b, kRadius, 1.5);
	const double tilt = 35 * M_PI / 180;
	const Eigen::Vector3d n =
	    Eigen::Vector3d(1, 0, 0).cross(Eigen::Vector3d(0, std::sin(tilt), std::cos(tilt)));
	EXPECT_GT(std::abs(c->normal.dot(n)), std::cos(3 * M_PI / 180));
	EXPECT_GT(c->t2 - c->t1, 1.9 * M_PI);  // the whole rim, its scanline parts included
	SceneOptions strings_only;
	strings_only.segments.enabled = false;
	const auto c0 = rim(strings_only);  // matched edgels only: the scanline parts are missing
	EXPECT_TRUE(!c0 || c0->t2 - c0->t1 < 1.5 * M_PI);
}

TEST(PieceStereo, ImagePiecesKeepAWholeEllipseAsOneArc)
{
	const auto rig = testRig();
	cv::Mat l, r;
	renderPair(obliqueDisc(), rig, l, r);
	const auto strings = detectEdgeStrings(l, EdgeOptions{});
	const auto pieces = segmentImageStrings(strings, l, FitOptions{});
	size_t arcs = 0, longest = 0;
	for (const auto& p : pieces)
		if (!p.is_line) ++arcs, longest = std::max(longest, p.hi - p.lo);
	EXPECT_GE(arcs, 1u);
	// the rim's outline (2π · 40 mm at 0.8 m, f = 700 px: about 220 px) is one arc, not quarters
	EXPECT_GT(longest, 150u);
}
