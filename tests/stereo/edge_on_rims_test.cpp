// Rims seen edge-on between two silhouettes (stereo/EdgeOnRims.h): the circle comes from the
// silhouettes' 3D lines where the straight rim piece meets them.
#include "SyntheticStereo.h"

#include <mrolr/stereo/EdgeOnRims.h>

#include <mrpt/config/CConfigFileMemory.h>

#include <gtest/gtest.h>

using namespace mrolr::stereo;
using namespace mrolr::stereo::test;

namespace
{
const Eigen::Vector3d kUp(0, 1, 0);  // thesis L: x left, y up, z forward (mm)

/** A horizontal circle's front arc between its two tangent points as seen from L's origin, as a
 * left edge string, and the one line piece of it; plus the body's silhouettes below the rim (the
 * vertical 3D lines through the tangent points, going down by 80 mm). */
struct EdgeOnRim
{
	std::vector<EdgeString> strings;
	std::vector<ImagePiece> pieces;
	std::vector<LineFit3> silhouettes;
};

EdgeOnRim edgeOnRim(const Rectifier& rect, const Eigen::Vector3d& c, double r)
{
	const Eigen::Vector3d h = Eigen::Vector3d(c.x(), 0, c.z()).normalized();  // view direction
	const Eigen::Vector3d side = kUp.cross(h);
	const double D = Eigen::Vector3d(c.x(), 0, c.z()).norm(), alpha = std::acos(r / D);
	EdgeOnRim out;
	EdgeString s;
	for (int i = 0; i <= 100; ++i)  // the front arc, from one tangent point to the other
	{
		const double t = -alpha + 2 * alpha * i / 100;
		const Eigen::Vector3d x = c + r * (-std::cos(t) * h + std::sin(t) * side);
		s.push_back({rect.leftPixelOf(x), {0, 1}});
	}
	out.strings = {s};
	ImagePiece p;
	p.string = 0, p.lo = 0, p.hi = s.size(), p.is_line = true;
	p.a = s.front().p, p.b = s.back().p;
	out.pieces = {p};
	for (const double t : {-alpha, alpha})
	{
		const Eigen::Vector3d x = c + r * (-std::cos(t) * h + std::sin(t) * side);
		out.silhouettes.push_back({x - 80 * kUp, x, 0, 30});
	}
	return out;
}
}  // namespace

TEST(EdgeOnRims, CircleFromTheTangentPointsOnTheSilhouettes)
{
	const Rectifier rect(testRig(0));
	EdgeOnRimOptions o;
	const Eigen::Vector3d c(40, 0, 900);  // at the camera's height: seen exactly edge-on
	const auto rim = edgeOnRim(rect, c, 35);
	const auto found = edgeOnRims(rim.strings, rim.pieces, rim.silhouettes, {}, kUp, rect, o);
	ASSERT_EQ(found.size(), 1u);
	EXPECT_LT((found[0].centre - c).norm(), 0.5);
	EXPECT_NEAR(found[0].a, 35, 0.2);
	EXPECT_NEAR(std::abs(found[0].normal.dot(kUp)), 1, 1e-9);
	// already there: not added again
	EXPECT_TRUE(edgeOnRims(rim.strings, rim.pieces, rim.silhouettes, found, kUp, rect, o).empty());
	// no silhouettes, or silhouettes that are not steep (a line along the table): nothing
	EXPECT_TRUE(edgeOnRims(rim.strings, rim.pieces, {}, {}, kUp, rect, o).empty());
	auto flat = rim.silhouettes;
	for (auto& l : flat) l.p1 = l.p2 + Eigen::Vector3d(0, -5, 80);
	EXPECT_TRUE(edgeOnRims(rim.strings, rim.pieces, flat, {}, kUp, rect, o).empty());
}

TEST(EdgeOnRims, BoxFaceSeenObliquelyIsNotARim)
{
	// the top edge of a box face turned 30° from the view between its two vertical edges: the
	// chord is not square to the view
	const Rectifier rect(testRig(0));
	const Eigen::Vector3d a(70, 0, 880), b = a + 70 * Eigen::Vector3d(-std::cos(M_PI / 6), 0,
	                                                                   std::sin(M_PI / 6));
	EdgeString s;
	for (int i = 0; i <= 60; ++i) s.push_back({rect.leftPixelOf(a + (b - a) * i / 60.0), {0, 1}});
	ImagePiece p;
	p.string = 0, p.lo = 0, p.hi = s.size(), p.is_line = true, p.a = s.front().p, p.b = s.back().p;
	const std::vector<LineFit3> edges = {{a - 80 * kUp, a, 0, 30}, {b - 80 * kUp, b, 0, 30}};
	EXPECT_TRUE(edgeOnRims({s}, {p}, edges, {}, kUp, rect, EdgeOnRimOptions{}).empty());
	EdgeOnRimOptions any_chord;  // the chord test is what refuses it: seen edge-on, the circle's
	any_chord.max_chord_view_cos = 1;  // image is as straight as the box's edge
	EXPECT_EQ(edgeOnRims({s}, {p}, edges, {}, kUp, rect, any_chord).size(), 1u);
}

TEST(EdgeOnRims, KeysAreReadAndChecked)
{
	mrpt::config::CConfigFileMemory cfg(
	    "[scene]\nedge_on_rims = true\nedge_on_rim_max_residual_px = 1.5\n"
	    "edge_on_rim_max_extension_px = 10\n");
	EdgeOnRimOptions o;
	o.loadFromConfigFile(cfg, "scene");
	EXPECT_TRUE(o.enabled);
	EXPECT_EQ(o.max_residual_px, 1.5);
	EXPECT_EQ(o.max_extension_px, 10);
	mrpt::config::CConfigFileMemory bad("[scene]\nedge_on_rim_max_chord_view_cos = 2\n");
	try
	{
		EdgeOnRimOptions().loadFromConfigFile(bad, "scene");
		ADD_FAILURE() << "accepted";
	}
	catch (const std::exception& e)
	{
		EXPECT_NE(std::string(e.what()).find("edge_on_rim_max_chord_view_cos"), std::string::npos)
		    << e.what();
	}
}
