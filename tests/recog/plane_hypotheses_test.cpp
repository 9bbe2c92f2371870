// Hypotheses from single features on the support plane (PlaneHypotheses.h): an upright object is
// among the hypotheses of one of its rims, one of its horizontal lines, a limb or two vertical
// edges seen alone; a line at the wrong height above the plane makes none; bad [plane_hypotheses]
// values are rejected; the shipped section equals the defaults. The recogniser with images:
// plane_recogniser_images_test.cpp.
#include "plane_test_util.h"
#include "recog_test_util.h"

#include <mrolr/recog/images/Limbs.h>
#include <mrolr/recog/plane/PlaneHypotheses.h>
#include <mrolr/sim/SyntheticObjects.h>
#include <mrolr/util/Cli.h>
#include <mrolr/util/Config.h>

#include <gtest/gtest.h>
#include <mrpt/config/CConfigFile.h>
#include <mrpt/config/CConfigFileMemory.h>

#include <array>
#include <random>
#include <sstream>

using namespace mrolr::recog;
using namespace mrolr::sim;
using namespace mrolr::recog::plane_test;

namespace
{
/** (rotation deg, translation mm) error of the hypothesis of @p hyps nearest to @p truth (by the
 * larger of the two numbers). */
std::pair<double, double> nearest(const std::vector<PlaneHypothesis>& hyps,
                                  const Eigen::Isometry3d& truth)
{
	std::pair<double, double> best{1e9, 1e9};
	for (const auto& h : hyps)
	{
		const double r = test::rotationErrorDeg(h.T_OinS, truth);
		const double t = test::translationErrorMm(h.T_OinS, truth);
		if (std::max(r, t) < std::max(best.first, best.second)) best = {r, t};
	}
	return best;
}

PlaneHypothesisGenerator generatorOf(const mrolr::model::WireFrame& m)
{
	return PlaneHypothesisGenerator(featuresOf(m), modelBaseZ_mm(m), PlaneHypothesisOptions());
}

}  // namespace

// A bottle's outline alone (one limb of its body, as stereo reconstructs it against the table):
// among the hypotheses is its true axis, standing on the plane; the bottle is symmetric about it,
// so the model origin (on the axis) is where it should be. The body (r 35) and the neck (r 15)
// are its cylinders; the cone between them is not.
TEST(PlaneHypotheses, BottleFromOneLimbAlone)
{
	const auto bottle = makeBottle();
	const auto gen = generatorOf(bottle);
	ASSERT_EQ(gen.limbCylinders().size(), 2u);
	const auto bodies = revolutionBodiesOf(featuresOf(bottle));
	ASSERT_EQ(bodies.size(), 1u);
	std::mt19937 rng(5);
	for (int trial = 0; trial < 8; ++trial)
	{
		const double yaw = std::uniform_real_distribution<double>(-M_PI, M_PI)(rng);
		const auto T = upright(table(), {40.0 * trial - 160, -190, 620 + 15.0 * trial}, yaw);
		const Eigen::Vector3d cam_O = T.inverse() * Eigen::Vector3d::Zero();
		const auto limbs = limbLines(bodies[0], cam_O);
		ASSERT_FALSE(limbs.empty());
		for (const auto& [a, b] : limbs)
		{
			if ((a - b).norm() < 100) continue;  // the body's two limbs (150 mm), not the neck's
			const auto hyps = gen.generate({lineFeature(T * a, T * b)}, table());
			ASSERT_FALSE(hyps.empty());
			double best_mm = 1e9;
			for (const auto& h : hyps)
			{
				EXPECT_TRUE(h.from_limb);
				EXPECT_NEAR(gen.baseOffset_mm(h.T_OinS, table()), 0.0, 1e-6);
				best_mm = std::min(best_mm, (h.T_OinS.translation() - T.translation()).norm());
			}
			EXPECT_LT(best_mm, 1e-6) << "trial " << trial;
		}
	}
	// the same limb raised 80 mm (above the body) or tilted 15 deg out of the normal makes none
	const auto T = upright(table(), {0, -190, 640}, 0.3);
	const auto limb = limbLines(bodies[0], T.inverse() * Eigen::Vector3d::Zero()).front();
	const Eigen::Vector3d up = 80 * table().n_S;
	EXPECT_TRUE(gen.generate({lineFeature(T * limb.first + up, T * limb.second + up)}, table())
	                .empty());
	const Eigen::Vector3d top = T * limb.second, bottom = T * limb.first;
	const Eigen::Vector3d side = table().n_S.cross(bottom).normalized();
	const Eigen::Vector3d tilted =
	    bottom + Eigen::AngleAxisd(15 * M_PI / 180, side) * (top - bottom);
	EXPECT_TRUE(gen.generate({lineFeature(bottom, tilted)}, table()).empty());
	// and with limb_hypotheses off, no cylinders
	PlaneHypothesisOptions off;
	off.limb_hypotheses = false;
	EXPECT_TRUE(
	    PlaneHypothesisGenerator(featuresOf(bottle), modelBaseZ_mm(bottle), off).limbCylinders()
	        .empty());
}

// A cup's top rim alone: among the hypotheses is the true pose up to its yaw (the rim's yaws are
// tried every 30°, the images' refinement sweeps finer).
TEST(PlaneHypotheses, CupFromItsTopRimAlone)
{
	const auto cup = makeCup();
	const auto fs = featuresOf(cup);
	const auto gen = generatorOf(cup);
	ASSERT_GE(gen.rims().size(), 2u);  // base and top rim at least
	size_t top = gen.rims()[0];
	for (const size_t r : gen.rims())
		if (fs[r].m.z() > fs[top].m.z()) top = r;
	std::mt19937 rng(7);
	for (int trial = 0; trial < 10; ++trial)
	{
		const double yaw = std::uniform_real_distribution<double>(-M_PI, M_PI)(rng);
		const auto T = upright(table(), {20.0 * trial - 100, -180, 600 + 10.0 * trial}, yaw);
		const auto hyps = gen.generate({fs[top].transformed(T)}, table());
		ASSERT_FALSE(hyps.empty());
		const auto [r, t] = nearest(hyps, T);
		// the rim's centre is on the axis: yaw within half the 30° step, the origin within 1 mm
		// of its place rotated about the axis (the base centre is on the axis)
		EXPECT_LE(r, 15.0 + 1e-6) << "trial " << trial;
		EXPECT_LT(t, 1.0) << "trial " << trial;
		for (const auto& h : hyps)
			EXPECT_NEAR(gen.baseOffset_mm(h.T_OinS, table()), 0.0, 1e-6);
	}
}

// One horizontal line of the stapler box, whole or as a fragment sharing one end, seen alone:
// the exact pose is among the hypotheses.
TEST(PlaneHypotheses, BoxFromOneHorizontalLine)
{
	const auto box = makeStaplerBox();
	const auto fs = featuresOf(box);
	const auto gen = generatorOf(box);
	std::mt19937 rng(11);
	for (const double z : {0.0, 55.0})
	{
		const size_t l = longestLineAt(fs, z);
		ASSERT_LT(l, fs.size());
		for (const double f : {1.0, 0.6, 0.3})
		{
			const double yaw = std::uniform_real_distribution<double>(-M_PI, M_PI)(rng);
			const auto T = upright(table(), {30, -190, 640}, yaw);
			Feature seen = fragment(fs[l], f).transformed(T);
			if (f < 0.5) seen = seen.flipped();  // stereo fixes no endpoint order
			const auto [r, t] = nearest(gen.generate({seen}, table()), T);
			EXPECT_LT(r, 1e-6) << "z " << z << " fragment " << f;
			EXPECT_LT(t, 1e-6) << "z " << z << " fragment " << f;
		}
	}
}

// Two vertical edges of a box as stereo recovers them against a wall (fragments, no horizontal
// edge): among the hypotheses is the box's true pose (both faces' widths, either order of the
// lines); lines further apart than any two edges, or above the box, make none; a model with
// cylinders (the bottle) and the option off get no edge pairs.
TEST(PlaneHypotheses, BoxFromTwoVerticalEdges)
{
	const auto box = makeStaplerBox();  // 160 x 45 x 55 mm
	const auto gen = generatorOf(box);
	ASSERT_EQ(gen.verticalEdgePairs().size(), 6u);  // 4 vertical edges
	std::mt19937 rng(17);
	const std::array<Eigen::Vector3d, 3> corners = {
	    Eigen::Vector3d(-80, -22.5, 0), Eigen::Vector3d(80, -22.5, 0), Eigen::Vector3d(80, 22.5, 0)};
	const Eigen::Vector3d up(0, 0, 55);
	for (int trial = 0; trial < 6; ++trial)
	{
		const double yaw = std::uniform_real_distribution<double>(-M_PI, M_PI)(rng);
		const auto T = upright(table(), {20.0 * trial - 50, -190, 640}, yaw);
		for (const auto& [a, b] : {std::pair<int, int>{0, 1}, {1, 2}, {2, 1}})
		{
			const Feature ea = lineFeature(T * (corners[a] + 0.1 * up), T * (corners[a] + 0.7 * up));
			const Feature eb = lineFeature(T * (corners[b] + 0.3 * up), T * (corners[b] + 0.9 * up));
			const auto hyps = gen.generate({ea, eb}, table());
			const auto [r, t] = nearest(hyps, T);
			EXPECT_LT(r, 1e-6) << "trial " << trial << " edges " << a << b;
			EXPECT_LT(t, 1e-6) << "trial " << trial << " edges " << a << b;
			for (const auto& h : hyps)
			{
				EXPECT_TRUE(h.from_edge_pair);
				EXPECT_NEAR(gen.baseOffset_mm(h.T_OinS, table()), 0.0, 1e-6);
			}
		}
	}
	const auto T = upright(table(), {0, -190, 640}, 0.4);
	const auto edge = [&](const Eigen::Vector3d& c, double lift)
	{ return lineFeature(T * (c + Eigen::Vector3d(0, 0, lift)), T * (c + up * 0.8)); };
	const Eigen::Vector3d wide(100, -22.5, 0);  // 180 mm from corner 0: no two edges are
	EXPECT_TRUE(gen.generate({edge(corners[0], 5), edge(wide, 5)}, table()).empty());
	const Eigen::Vector3d above(0, 0, 80);
	EXPECT_TRUE(gen.generate({lineFeature(T * (corners[0] + above), T * (corners[0] + 2 * above)),
	                          lineFeature(T * (corners[1] + above), T * (corners[1] + 2 * above))},
	                         table())
	                .empty());
	EXPECT_TRUE(generatorOf(makeBottle()).verticalEdgePairs().empty());
	PlaneHypothesisOptions off;
	off.edge_pair_hypotheses = false;
	EXPECT_TRUE(
	    PlaneHypothesisGenerator(featuresOf(box), modelBaseZ_mm(box), off).verticalEdgePairs()
	        .empty());
}

// The same base line 30 mm above the table (where the box has no horizontal line) or tilted 20°
// out of the horizontal makes no hypothesis.
TEST(PlaneHypotheses, NoHypothesisFromALineAtTheWrongHeightOrTilt)
{
	const auto box = makeStaplerBox();
	const auto fs = featuresOf(box);
	const auto gen = generatorOf(box);
	const auto T = upright(table(), {30, -190, 640}, 0.4);
	const size_t l = longestLineAt(fs, 0);
	ASSERT_FALSE(gen.generate({fs[l].transformed(T)}, table()).empty());
	Feature raised = fs[l].transformed(T);
	for (auto* p : {&raised.p1, &raised.p2, &raised.m}) *p += 30 * table().n_S;
	EXPECT_TRUE(gen.generate({raised}, table()).empty());
	Feature tilted = fs[l];
	tilted.p2 = tilted.p1 + Eigen::AngleAxisd(20 * M_PI / 180, Eigen::Vector3d::UnitY()) *
	                            (tilted.p2 - tilted.p1);
	tilted.u = (tilted.p2 - tilted.p1).normalized();
	tilted.m = 0.5 * (tilted.p1 + tilted.p2);
	EXPECT_TRUE(gen.generate({tilted.transformed(T)}, table()).empty());
	// and a cup's rim of another radius makes none for the cup
	const auto cup = makeCup();
	const auto cf = featuresOf(cup);
	const auto cgen = generatorOf(cup);
	Feature rim = cf[cgen.rims()[0]];
	rim.a_mm += 15, rim.b_mm += 15;
	EXPECT_TRUE(cgen.generate({rim.transformed(upright(table(), {0, -200, 650}, 0))}, table())
	                .empty());
}

TEST(PlaneHypotheses, OptionsRejectBadValues)
{
	const std::string good =
	    "[p]\nenable = true\nrun_when = not_found\nrim_normal_tol_deg = 15\n"
	    "scene_normal_tol_deg = 20\nradius_tol_mm = 6\nheight_tol_mm = 10\n"
	    "horizontal_tol_deg = 10\nmin_line_mm = 15\nmax_length_ratio = 1.2\n"
	    "rim_yaw_step_deg = 30\nmax_hypotheses = 30\nprerank_spacing_mm = 9\n"
	    "min_image_score = 0.7\nmax_base_offset_mm = 15\n";
	PlaneHypothesisOptions o;
	EXPECT_NO_THROW(o.loadFromConfigFile(mrpt::config::CConfigFileMemory(good), "p"));
	const std::vector<std::pair<std::string, std::string>> bad = {
	    {"run_when = not_found", "run_when = sometimes"},
	    {"height_tol_mm = 10", "height_tol_mm = -1"},
	    {"max_hypotheses = 30", "max_hypotheses = 0"},
	    {"min_image_score = 0.7", "min_image_score = 1.5"},
	    {"enable = true", "enable = maybe"},
	    {"radius_tol_mm = 6", "radius_tol_mm = six"},
	    {"enable = true\n", ""},
	    {"max_base_offset_mm = 15\n", "max_base_offset_mm = 15\nlimb_vertical_tol_deg = 95\n"},
	    {"max_base_offset_mm = 15\n", "max_base_offset_mm = 15\nlimb_hypotheses = often\n"},
	    {"max_base_offset_mm = 15\n", "max_base_offset_mm = 15\nlimb_min_mm = -2\n"},
	    {"max_base_offset_mm = 15\n", "max_base_offset_mm = 15\nedge_pair_hypotheses = 2x\n"},
	    {"max_base_offset_mm = 15\n", "max_base_offset_mm = 15\nedge_pair_min_mm = -1\n"},
	    {"max_base_offset_mm = 15\n", "max_base_offset_mm = 15\nedge_pair_width_tol_mm = x\n"},
	    {"max_base_offset_mm = 15\n",
	     "max_base_offset_mm = 15\nedge_pair_min_image_score = 1.5\n"}};
	for (const auto& [from, to] : bad)
	{
		std::string text = good;
		text.replace(text.find(from), from.size(), to);
		// a new object each time: setContent merges with what was read before
		const mrpt::config::CConfigFileMemory cfg(text);
		// an optional key added after max_base_offset_mm is the one named
		const size_t added = to.find('\n');
		const std::string key = added != std::string::npos && added + 1 < to.size()
		                            ? to.substr(added + 1, to.find(' ', added) - added - 1)
		                            : from.substr(0, from.find(' '));
		try
		{
			PlaneHypothesisOptions q;
			q.loadFromConfigFile(cfg, "p");
			FAIL() << "accepted: " << to;
		}
		catch (const mrolr::util::ConfigError& e)
		{
			EXPECT_NE(std::string(e.what()).find(key), std::string::npos) << e.what();
		}
	}
	// no section: the defaults
	PlaneHypothesisOptions d;
	d.min_image_score = 0.9;
	d.loadFromConfigFile(mrpt::config::CConfigFileMemory(std::string("[other]\nx = 1\n")), "p");
	EXPECT_EQ(d.min_image_score, 0.9);
	// the limb keys are optional (files written before them load with the defaults); given, read
	PlaneHypothesisOptions older;
	older.loadFromConfigFile(mrpt::config::CConfigFileMemory(good), "p");
	EXPECT_TRUE(older.limb_hypotheses);
	EXPECT_EQ(older.limb_min_mm, PlaneHypothesisOptions().limb_min_mm);
	PlaneHypothesisOptions newer;
	newer.loadFromConfigFile(
	    mrpt::config::CConfigFileMemory(good + "limb_hypotheses = false\nlimb_min_mm = 33\n"),
	    "p");
	EXPECT_FALSE(newer.limb_hypotheses);
	EXPECT_EQ(newer.limb_min_mm, 33);
	EXPECT_TRUE(older.edge_pair_hypotheses);
	EXPECT_EQ(older.edge_pair_min_mm, PlaneHypothesisOptions().edge_pair_min_mm);
	PlaneHypothesisOptions pairs;
	pairs.loadFromConfigFile(mrpt::config::CConfigFileMemory(
	                             good + "edge_pair_hypotheses = false\nedge_pair_width_tol_mm = 2\n"),
	                         "p");
	EXPECT_FALSE(pairs.edge_pair_hypotheses);
	EXPECT_EQ(pairs.edge_pair_width_tol_mm, 2);
}

TEST(PlaneHypotheses, ShippedOptionsAreTheDefaults)
{
	const mrpt::config::CConfigFile cfg(mrolr::util::requireProjectFile("config/recognition.ini"));
	PlaneHypothesisOptions shipped;  // the file states `enable`; every tolerance is the default
	shipped.loadFromConfigFile(cfg, "plane_hypotheses");
	std::ostringstream a, b;
	shipped.dump(a);
	PlaneHypothesisOptions().dump(b);
	EXPECT_EQ(a.str(), b.str());
}

TEST(PlaneHypotheses, SupportPlaneFromPointAndNormal)
{
	const auto p = SupportPlane::through({1, 2, 3}, {0, 2, 0});
	EXPECT_NEAR(p.n_S.norm(), 1.0, 1e-12);
	EXPECT_NEAR(p.height_mm({5, 2, -7}), 0.0, 1e-12);
	EXPECT_NEAR(p.height_mm({5, 12, -7}), 10.0, 1e-12);
	const auto q = SupportPlane::fromCoefficients({0, 0, 2}, -10);
	EXPECT_NEAR(q.height_mm({0, 0, 5}), 0.0, 1e-12);
	EXPECT_THROW(SupportPlane::fromCoefficients({0, 0, 0}, 1), std::invalid_argument);
}
