// Piece stereo (stereo/SegmentStereo.h): a rim seen obliquely runs along the scanlines at its top
// and bottom, where edgel matching has nothing to hold on to; the pair of image ellipses still
// gives the whole conic (row crossings and epipolar tangencies correspond).
#include "SyntheticStereo.h"

#include <mrolr/stereo/CornerPairStereo.h>
#include <mrolr/stereo/ImagePieces.h>
#include <mrolr/stereo/SceneReconstruction.h>

#include <mrpt/config/CConfigFileMemory.h>

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
	const auto c = rim(stepDefaults());
	ASSERT_TRUE(c.has_value());
	EXPECT_LT((c->centre - kCentre).norm(), 3.0);
	EXPECT_NEAR(c->a, kRadius, 1.5);
	EXPECT_NEAR(c->b, kRadius, 1.5);
	const double tilt = 35 * M_PI / 180;
	const Eigen::Vector3d n =
	    Eigen::Vector3d(1, 0, 0).cross(Eigen::Vector3d(0, std::sin(tilt), std::cos(tilt)));
	EXPECT_GT(std::abs(c->normal.dot(n)), std::cos(3 * M_PI / 180));
	EXPECT_GT(c->t2 - c->t1, 1.9 * M_PI);  // the whole rim, its scanline parts included
	SceneOptions strings_only = stepDefaults();
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

namespace
{
/** An image line piece from a to b (px), grey 100 above and 30 below. */
ImagePiece segment(cv::Point2d a, cv::Point2d b)
{
	ImagePiece p;
	p.is_line = true;
	p.a = a.y <= b.y ? a : b;
	p.b = a.y <= b.y ? b : a;
	p.side_left = 100;
	p.side_right = 30;
	p.hi = 20;
	return p;
}

/** A box face's top edge along the scanlines from corner (x1, y1) to corner (x2, y2) with the two
 * side edges running down from the corners; the pieces stop 2 px short of the corners, as edge
 * chains break there. */
std::vector<ImagePiece> faceTop(double x1, double y1, double x2, double y2)
{
	const double s = (y2 - y1) / (x2 - x1);
	return {segment({x1 + 2, y1 + 2 * s}, {x2 - 2, y2 - 2 * s}),
	        segment({x1 - 0.2, y1 + 2}, {x1 - 4, y1 + 40}),
	        segment({x2 + 0.4, y2 + 2}, {x2 + 8, y2 + 40})};
}
}  // namespace

TEST(PieceStereo, EdgeAlongTheScanlinesFromItsTwoCorners)
{
	const Rectifier rect(testRig());
	const std::vector<EdgeString> none;
	const std::vector<EdgeMatch> no_matches;
	const auto left = faceTop(200, 150, 300, 153);
	const double d1 = 60, d2 = 56;  // the right end is farther away
	const auto right = faceTop(200 - d1, 150, 300 - d2, 153);
	const PieceStereoInput in{none, left, right, no_matches, 10, 200, &none};
	const auto l = cornerPairLine(in, 0, rect, SegmentStereoOptions{});
	ASSERT_TRUE(l.has_value());
	// the corners are the intersections with the side edges, not the piece's own ends
	const Eigen::Vector3d c1 = rect.pointInLeftCamera(200, 150, d1);
	const Eigen::Vector3d c2 = rect.pointInLeftCamera(300, 153, d2);
	EXPECT_LT((l->p1 - c1).norm(), 1e-6 * (c1 - c2).norm());
	EXPECT_LT((l->p2 - c2).norm(), 1e-6 * (c1 - c2).norm());
	// a right edge whose corners are on other rows is not the same edge
	const auto shifted = faceTop(200 - d1, 152, 300 - d2, 155);
	EXPECT_FALSE(cornerPairLine({none, left, shifted, no_matches, 10, 200, &none}, 0, rect,
	                            SegmentStereoOptions{}));
	// two equally good right edges: ambiguous, nothing is guessed
	auto twice = right;
	const auto other = faceTop(200 - 40, 150, 300 - 36, 153);
	twice.insert(twice.end(), other.begin(), other.end());
	EXPECT_FALSE(cornerPairLine({none, left, twice, no_matches, 10, 200, &none}, 0, rect,
	                            SegmentStereoOptions{}));
	// a side edge is not along the scanlines: no corner pair for it
	EXPECT_FALSE(cornerPairLine(in, 1, rect, SegmentStereoOptions{}));
}

TEST(PieceStereo, ShortPiecesMustMatchOnBothSides)
{
	const Rectifier rect(testRig());
	const std::vector<EdgeString> none;
	const std::vector<EdgeMatch> no_matches;
	auto l = segment({100, 100}, {101, 108}), r = segment({80, 100}, {81, 108});
	l.hi = r.hi = 8;    // 8 edgels: a short piece (a letter's stroke)
	r.side_right = 60;  // the right image's grey on one side differs: an occluding contour
	const std::vector<ImagePiece> lp{l}, rp{r};
	const PieceStereoInput in{none, lp, rp, no_matches, 10, 200, &none};
	const auto count = [&](int both_sides_below)
	{
		SegmentStereoOptions o;
		o.both_sides_below_edgels = both_sides_below;
		std::vector<LineFit3> lines;
		std::vector<ConicFit3> conics;
		reconstructPieces(in, rect, FitOptions{}, o, lines, conics);
		return lines.size();
	};
	EXPECT_EQ(count(0), 1u);   // one side agreeing is enough for a long piece
	EXPECT_EQ(count(10), 0u);  // not for a short one
	EXPECT_EQ(count(8), 1u);   // 8 edgels is not below 8
}

namespace
{
/** A line piece from a to b (a above b) with the grey levels of its two sides. */
ImagePiece linePiece(int string, cv::Point2d a, cv::Point2d b, double side_l, double side_r)
{
	ImagePiece p;
	p.string = string, p.lo = 0, p.hi = 20, p.is_line = true, p.a = a, p.b = b;
	p.side_left = side_l, p.side_right = side_r;
	return p;
}
}  // namespace

TEST(PieceStereo, CornerConsistencyChoosesBetweenTwoCandidates)
{
	// left piece A ends at the top of piece B (a corner at row 120); B has one right partner at
	// disparity 20. A has two: the true one at disparity 20 and one at 40 whose grey sides agree
	// a little better (an edge of a face only the right camera sees)
	const Rectifier rect(testRig(0));
	const std::vector<EdgeString> strings(2, EdgeString(20));
	const std::vector<EdgeMatch> no_matches;
	const std::vector<ImagePiece> left = {linePiece(0, {300, 100}, {300, 120}, 150, 30),
	                                      linePiece(1, {300, 121}, {310, 180}, 150, 60)};
	const std::vector<ImagePiece> right = {linePiece(0, {280, 100}, {280, 120}, 155, 90),
	                                       linePiece(0, {260, 100}, {260, 118}, 90, 31),
	                                       linePiece(1, {280, 121}, {290, 180}, 150, 60)};
	const PieceStereoInput in{strings, left, right, no_matches, 5, 100, &strings};
	const auto depthOfA = [&](double consistency_px)
	{
		SegmentStereoOptions o;
		o.corner_consistency_px = consistency_px;
		std::vector<LineFit3> lines;
		std::vector<ConicFit3> conics;
		reconstructPieces(in, rect, FitOptions{}, o, lines, conics);
		EXPECT_EQ(lines.size(), 2u);
		const Eigen::Vector3d top = rect.pointInLeftCamera(300, 100, 20);
		double z = 0, best = 1e9;
		for (const auto& l : lines)  // the line whose image is A's: same direction from the camera
			if (const double e = (l.p1.normalized() - top.normalized()).norm(); e < best)
				best = e, z = l.p1.z();
		return z;
	};
	const double z20 = rect.pointInLeftCamera(300, 100, 20).z();
	EXPECT_NEAR(depthOfA(0), z20 / 2, 0.01 * z20);  // off: the better grey wins, disparity 40
	EXPECT_NEAR(depthOfA(4), z20, 0.01 * z20);      // on: consistent with B's corner
}

namespace
{
/** Edgels every pixel from a to b (px), gradient across the segment. */
EdgeString edgelsAlong(cv::Point2d a, cv::Point2d b)
{
	const double len = cv::norm(b - a);
	const cv::Point2d u = (b - a) / len;
	EdgeString s;
	for (int k = 0; k <= static_cast<int>(len); ++k)
		s.push_back({a + u * static_cast<double>(k), {u.y, -u.x}});
	return s;
}
}  // namespace

TEST(PieceStereo, ShortUnpairedEdgePlacedFromItsCorners)
{
	// left: vertical edges A and B joined by C, which crosses the scanlines at 56°; the right
	// image has A and B as segments (disparities 20 and 24) but C only as edgels (a short piece
	// of a longer string there): C's ends take A's and B's disparities
	const Rectifier rect(testRig(0));
	const std::vector<EdgeMatch> no_matches;
	const std::vector<EdgeString> left_strings(3, EdgeString(60));
	const std::vector<ImagePiece> left = {linePiece(0, {300, 100}, {300, 160}, 150, 30),
	                                      linePiece(1, {300, 160}, {320, 190}, 150, 60),
	                                      linePiece(2, {320, 190}, {320, 250}, 150, 60)};
	const std::vector<ImagePiece> right = {linePiece(0, {280, 100}, {280, 160}, 150, 30),
	                                       linePiece(2, {296, 190}, {296, 250}, 150, 60)};
	const std::vector<EdgeString> with_c = {edgelsAlong({280, 160}, {296, 190})};
	const std::vector<EdgeString> without_c = {edgelsAlong({380, 160}, {396, 190})};
	const auto lines = [&](const std::vector<EdgeString>& right_strings, bool corner_lines)
	{
		SegmentStereoOptions o;
		o.corner_lines = corner_lines;
		std::vector<LineFit3> out;
		std::vector<ConicFit3> conics;
		reconstructPieces({left_strings, left, right, no_matches, 5, 100, &right_strings}, rect,
		                  FitOptions{}, o, out, conics);
		return out;
	};
	const auto placed = lines(with_c, true);
	ASSERT_EQ(placed.size(), 3u);
	const Eigen::Vector3d c1 = rect.pointInLeftCamera(300, 160, 20),
	                      c2 = rect.pointInLeftCamera(320, 190, 24);
	EXPECT_LT((placed[1].p1 - c1).norm(), 1e-6 * c1.norm());
	EXPECT_LT((placed[1].p2 - c2).norm(), 1e-6 * c2.norm());
	EXPECT_EQ(lines(without_c, true).size(), 2u);  // nothing in the right image there
	EXPECT_EQ(lines(with_c, false).size(), 2u);    // off
}

TEST(PieceStereo, CornerLineKeysAreReadAndChecked)
{
	mrpt::config::CConfigFileMemory cfg(
	    "[scene]\nsegment_corner_lines = false\nsegment_corner_line_min_support = 0.5\n");
	SegmentStereoOptions o;
	o.loadFromConfigFile(cfg, "scene");
	EXPECT_FALSE(o.corner_lines);
	EXPECT_EQ(o.corner_line_min_support, 0.5);
	for (const char* bad : {"0", "1.5", "x"})
	{
		mrpt::config::CConfigFileMemory b(std::string("[scene]\nsegment_corner_line_min_support = ") +
		                                  bad + "\n");
		try
		{
			SegmentStereoOptions().loadFromConfigFile(b, "scene");
			ADD_FAILURE() << bad << " accepted";
		}
		catch (const std::exception& e)
		{
			EXPECT_NE(std::string(e.what()).find("segment_corner_line_min_support"),
			          std::string::npos)
			    << e.what();
		}
	}
}
