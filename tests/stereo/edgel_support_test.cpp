// Edgel support of a predicted segment (stereo/EdgelSupport.h).
#include <mrolr/stereo/EdgelSupport.h>

#include <gtest/gtest.h>

using namespace mrolr::stereo;

namespace
{
/** Edgels every pixel along the row y from x0 to x1, gradient along +y (an edge along the row). */
EdgeString rowEdge(double y, int x0, int x1)
{
	EdgeString s;
	for (int x = x0; x <= x1; ++x) s.push_back({{static_cast<double>(x), y}, {0, 1}});
	return s;
}
}  // namespace

TEST(EdgelSupport, FractionOfTheSegmentOnEdgelsAlongIt)
{
	const std::vector<EdgeString> edge = {rowEdge(50.3, 100, 200)};
	EXPECT_DOUBLE_EQ(edgelSupport(edge, {100, 50}, {200, 50}, 10), 1.0);
	EXPECT_DOUBLE_EQ(edgelSupport(edge, {200, 50}, {100, 50}, 10), 1.0);  // either sense
	// half of it beyond the edge's end
	EXPECT_NEAR(edgelSupport(edge, {150, 50}, {250, 50}, 10), 0.5, 0.02);
	// 3 px off the edge: none (radius 1 px), unless the radius allows it
	EXPECT_DOUBLE_EQ(edgelSupport(edge, {100, 53.3}, {200, 53.3}, 10), 0.0);
	EXPECT_DOUBLE_EQ(edgelSupport(edge, {100, 53.3}, {200, 53.3}, 10, 3.5), 1.0);
	// crossing the edge at 90°: the edgels there run the wrong way
	EXPECT_DOUBLE_EQ(edgelSupport(edge, {150, 20}, {150, 80}, 30), 0.0);
	EXPECT_GT(edgelSupport(edge, {150, 20}, {150, 80}, 90), 0.0);
	// too short to say
	EXPECT_DOUBLE_EQ(edgelSupport(edge, {150, 50}, {151, 50}, 10), 0.0);
	EXPECT_DOUBLE_EQ(edgelSupport({}, {100, 50}, {200, 50}, 10), 0.0);
}
