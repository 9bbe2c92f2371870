#include <mrolr/model/WireFrameIO.h>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>
#include <sstream>

using namespace mrolr::model;

namespace
{
WireFrame randomModel(std::mt19937& rng)
{
	std::uniform_real_distribution<double> u(-500, 500);
	auto rv = [&] { return Eigen::Vector3d(u(rng), u(rng), u(rng)); };
	WireFrame wf;
	wf.frame = WireFrameFrame::LeftCamera;
	for (int i = 1; i <= 5; ++i) wf.lines.push_back({i, rv(), rv()});
	Conic3 c;
	c.id = 9;
	c.centre = rv();
	c.normal = rv().normalized();
	c.major = c.normal.unitOrthogonal();
	c.a = 1.0 / 3.0 * 100;
	c.b = 0.1 * c.a;
	c.t1 = -M_PI / 7;
	c.t2 = 2 * M_PI / 3;
	wf.conics.push_back(c);
	wf.has_grasp = true;
	wf.grasp = {rv(), 1.0 / 7, -2.0 / 3, 179.9};
	wf.cliques.push_back({9, {1, 2, 3}});
	return wf;
}

std::string header(const std::string& body)
{
	return "# mrolr wire-frame 1\nunits mm\nframe object\n" + body;
}

/** The line number an error reports for @p text, or -1 when it parses. */
int errorLine(const std::string& text)
{
	std::istringstream in(text);
	try
	{
		readWireFrame(in, "t.wf");
	}
	catch (const WireFrameFormatError& e)
	{
		EXPECT_NE(std::string(e.what()).find("t.wf:" + std::to_string(e.lineNumber())),
		          std::string::npos);
		return e.lineNumber();
	}
	return -1;
}
}  // namespace

TEST(WireFrameIO, WriteThenReadIsBitExact)
{
	std::mt19937 rng(3);
	for (int trial = 0; trial < 20; ++trial)
	{
		const WireFrame wf = randomModel(rng);
		std::stringstream ss;
		writeWireFrame(wf, ss);
		const WireFrame back = readWireFrame(ss);
		ASSERT_EQ(back.lines.size(), wf.lines.size());
		for (size_t i = 0; i < wf.lines.size(); ++i)
		{
			EXPECT_EQ(back.lines[i].id, wf.lines[i].id);
			EXPECT_TRUE(back.lines[i].p1 == wf.lines[i].p1);
			EXPECT_TRUE(back.lines[i].p2 == wf.lines[i].p2);
		}
		const Conic3 &c = wf.conics[0], &d = back.conics.at(0);
		EXPECT_TRUE(c.centre == d.centre && c.normal == d.normal && c.major == d.major);
		EXPECT_TRUE(c.a == d.a && c.b == d.b && c.t1 == d.t1 && c.t2 == d.t2);
		EXPECT_TRUE(back.has_grasp && back.grasp.p_mm == wf.grasp.p_mm);
		EXPECT_EQ(back.grasp.roll_deg, wf.grasp.roll_deg);
		EXPECT_EQ(back.frame, WireFrameFrame::LeftCamera);
		ASSERT_EQ(back.cliques.size(), 1u);
		EXPECT_EQ(back.cliques[0].members, wf.cliques[0].members);
	}
}

TEST(WireFrameIO, ReadsCommentsAndNormalisesHandWrittenVectors)
{
	std::istringstream in(header(
	    "# a comment\n\nline 1 0 0 0 10 0 0  # trailing\nconic 2 0 0 0 0 0 2 3 0 0 5 5 0 6.28\n"));
	const WireFrame wf = readWireFrame(in);
	ASSERT_EQ(wf.lines.size(), 1u);
	ASSERT_EQ(wf.conics.size(), 1u);
	EXPECT_DOUBLE_EQ(wf.conics[0].normal.norm(), 1.0);
	EXPECT_DOUBLE_EQ(wf.conics[0].major.x(), 1.0);
	EXPECT_DOUBLE_EQ(wf.lines[0].length(), 10.0);
}

TEST(WireFrameIO, AConicWrittenWithFourDecimalsLoadsWithItsAxesPerpendicular)
{
	// a plane tilted 30° about x, its major axis turned 40° in it, every number to four decimals
	const Eigen::Vector3d n(0, -0.5, 0.8660254037844386);
	const Eigen::Vector3d m =
	    std::cos(0.6981317) * Eigen::Vector3d::UnitX() + std::sin(0.6981317) * n.cross(Eigen::Vector3d::UnitX());
	char line[256];
	std::snprintf(line, sizeof line, "conic 2 0 0 0 %.4f %.4f %.4f %.4f %.4f %.4f 5 4 0 6.2832\n",
	              n.x(), n.y(), n.z(), m.x(), m.y(), m.z());
	std::istringstream in(header(line));
	const WireFrame wf = readWireFrame(in);
	ASSERT_EQ(wf.conics.size(), 1u);
	const auto& c = wf.conics[0];
	EXPECT_GT(std::abs(Eigen::Vector3d(std::round(m.x() * 1e4) / 1e4, std::round(m.y() * 1e4) / 1e4,
	                                   std::round(m.z() * 1e4) / 1e4)
	                       .normalized()
	                       .dot(c.normal)),
	          1e-6);                                // the file's axes were not perpendicular
	EXPECT_NEAR(c.normal.dot(c.major), 0.0, 1e-15);  // the loaded ones are
	EXPECT_NEAR(c.major.norm(), 1.0, 1e-15);
	EXPECT_LT((c.major - m).norm(), 1e-4);  // and the axis is where the file put it
	// a lean that rounding does not explain (2°) is still an error on its line
	EXPECT_EQ(errorLine(header("conic 2 0 0 0 0 0 1 0.99939 0 0.0349 5 5 0 1\n")), 4);
}

TEST(WireFrameIO, RejectsMalformedLinesWithTheirLineNumber)
{
	EXPECT_EQ(errorLine(header("line 1 0 0 0 1 1\n")), 4);                        // too few fields
	EXPECT_EQ(errorLine(header("line 1 0 0 0 1 1 x\n")), 4);                      // not a number
	EXPECT_EQ(errorLine(header("line 0 0 0 0 1 1 1\n")), 4);                      // id not positive
	EXPECT_EQ(errorLine(header("line 1 0 0 0 1 1 1\nline 1 0 0 0 2 2 2\n")), 5);  // duplicate
	EXPECT_EQ(errorLine(header("\nconic 2 0 0 0 0 0 1 0 0 1 5 5 0 1\n")), 5);  // major ⟂ normal
	EXPECT_EQ(errorLine(header("conic 2 0 0 0 0 0 1 1 0 0 4 5 0 1\n")), 4);    // a < b
	EXPECT_EQ(errorLine(header("conic 2 0 0 0 0 0 1 1 0 0 5 5 1 1\n")), 4);    // empty arc
	EXPECT_EQ(errorLine(header("polygon 1 2 3\n")), 4);
	EXPECT_EQ(errorLine(header("clique 1 2 1\n")), 4);  // N disagrees
	EXPECT_EQ(errorLine(header("grasp 0 0 0 0 0 0\ngrasp 0 0 0 0 0 0\n")), 5);
	EXPECT_EQ(errorLine("units mm\n"), 1);  // header missing
	EXPECT_EQ(errorLine("# mrolr wire-frame 1\nunits cm\n"), 2);
	EXPECT_EQ(errorLine("# mrolr wire-frame 1\nunits mm\nframe world\n"), 3);
	EXPECT_EQ(errorLine(header("line 1 0 0 0 1 1 nan\n")), 4);
	EXPECT_EQ(errorLine(header("line 1 0 0 0 1 1 1\n")), -1);
}

TEST(WireFrameIO, RejectsCliquesNamingUnknownIdsAndMissingHeaderLines)
{
	EXPECT_GT(errorLine(header("line 1 0 0 0 1 1 1\nclique 1 2 1 7\n")), 0);
	EXPECT_GT(errorLine("# mrolr wire-frame 1\nframe object\n"), 0);  // units missing
	EXPECT_GT(errorLine(""), -1);
	EXPECT_THROW(loadWireFrame("/nonexistent/x.wf"), std::runtime_error);
}
