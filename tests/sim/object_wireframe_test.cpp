#include <mrolr/model/WireFrameIO.h>
#include <mrolr/sim/ObjectWireFrame.h>

#include <gtest/gtest.h>

#include <cstdio>

using namespace mrolr;

namespace
{
world::ObjectShape load(const std::string& name)
{
	return world::ObjectShape::load(std::string(MROLR_SOURCE_DIR) + "/datasets/objects/" + name +
	                                ".ini");
}

bool onCubeSurface(const Eigen::Vector3d& p)
{
	const bool inside = std::abs(p.x()) <= 30 + 1e-9 && std::abs(p.y()) <= 30 + 1e-9 &&
	                    p.z() >= -1e-9 && p.z() <= 60 + 1e-9;
	const bool onFace = std::abs(std::abs(p.x()) - 30) < 1e-9 ||
	                    std::abs(std::abs(p.y()) - 30) < 1e-9 || std::abs(p.z()) < 1e-9 ||
	                    std::abs(p.z() - 60) < 1e-9;
	return inside && onFace;
}
}  // namespace

TEST(ObjectWireFrame, CubeEdgesAndLettersLieOnItsFaces)
{
	const auto wf = sim::objectWireFrame(load("alphabet_cube"));
	EXPECT_EQ(wf.frame, model::WireFrameFrame::Object);
	ASSERT_GT(wf.lines.size(), 12u);  // 12 edges plus the strokes of 5 letters
	EXPECT_TRUE(wf.conics.empty());
	for (size_t i = 0; i < 12; ++i) EXPECT_NEAR(wf.lines[i].length(), 60, 1e-9);
	for (const auto& l : wf.lines)
	{
		EXPECT_TRUE(onCubeSurface(l.p1)) << "line " << l.id;
		EXPECT_TRUE(onCubeSurface(l.p2)) << "line " << l.id;
	}
	EXPECT_TRUE(wf.has_grasp);
}

TEST(ObjectWireFrame, CupRimsAndHandleArcs)
{
	const auto wf = sim::objectWireFrame(load("cup"));
	EXPECT_TRUE(wf.lines.empty());
	ASSERT_EQ(wf.conics.size(), 6u);  // two rims, four handle edges
	EXPECT_NEAR(wf.conics[0].a, 40, 1e-12);
	EXPECT_NEAR(wf.conics[1].centre.z(), 95, 1e-12);
	for (size_t i = 2; i < 6; ++i)
	{
		const auto& c = wf.conics[i];
		// the handle's arcs start and end on the body (x = 40 at the ring's centre plane) and bulge
		// outwards, away from the body
		EXPECT_NEAR(c.pointAt(c.t1).x(), 40, 1e-9);
		EXPECT_NEAR(c.pointAt(c.t2).x(), 40, 1e-9);
		EXPECT_GT(c.pointAt(0.5 * (c.t1 + c.t2)).x(), 55);
		EXPECT_LT(c.pointAt(c.t1).z(), c.pointAt(c.t2).z());
	}
}

TEST(ObjectWireFrame, SharedRimsAreKeptOnce)
{
	// bottle: body bottom, body top = shoulder bottom, shoulder top = neck bottom, neck top
	EXPECT_EQ(sim::objectWireFrame(load("bottle")).conics.size(), 4u);
}

TEST(ObjectWireFrame, RoundTripThroughTheWfFormat)
{
	const auto wf = sim::objectWireFrame(load("hole_punch"));
	const std::string path = testing::TempDir() + "/hole_punch_truth.wf";
	model::saveWireFrame(wf, path);
	const auto back = model::loadWireFrame(path);
	ASSERT_EQ(back.lines.size(), wf.lines.size());
	for (size_t i = 0; i < wf.lines.size(); ++i)
		EXPECT_LT((back.lines[i].p1 - wf.lines[i].p1).norm(), 1e-9);
	std::remove(path.c_str());
}
