#include <mrolr/recog/ModelTable.h>
#include <mrolr/recog/PairRelation.h>
#include <mrolr/sim/SyntheticObjects.h>

#include "recog_test_util.h"

#include <gtest/gtest.h>

#include <random>

using namespace mrolr::recog;
using test::randomPose;
using namespace mrolr::sim;

namespace
{
Feature line(Eigen::Vector3d a, Eigen::Vector3d b)
{
	mrolr::model::WireFrame wf;
	wf.lines.push_back({1, a, b});
	return featuresOf(wf).front();
}
}  // namespace

// The paper's quantities for two perpendicular skew lines worked by hand.
TEST(PairRelation, SkewLinesByHand)
{
	const auto a = line({0, 0, 0}, {100, 0, 0});
	const auto b = line({30, -20, 10}, {30, 40, 10});
	const auto r = relateModel(a, b);
	EXPECT_FALSE(r.parallel);
	EXPECT_NEAR(r.alpha, M_PI / 2, 1e-12);
	EXPECT_NEAR(r.h, 10, 1e-12);        // d = x × y = z, m2 - m1 has z = 10
	EXPECT_NEAR(r.q1, 30 - 50, 1e-12);  // closest point x = 30, midpoint x = 50
	EXPECT_NEAR(r.q2, 0 - 10, 1e-12);   // closest point y = 0, midpoint y = 10
	EXPECT_NEAR(r.lo1, -30, 1e-12);
	EXPECT_NEAR(r.hi1, 70, 1e-12);
	EXPECT_NEAR(r.lo2, -20, 1e-12);
	EXPECT_NEAR(r.hi2, 40, 1e-12);
}

// Relations are invariant under rigid motion: every model pair is consistent with its own image
// under a random pose, at zero tolerance up to rounding.
TEST(PairRelation, InvariantUnderRigidMotion)
{
	std::mt19937 rng(7);
	const Tolerance tiny{1e-6, 1e-6};  // acos near 0 and pi loses about 1e-8 rad
	for (const auto& wf : makeLabObjects())
	{
		const auto fs = featuresOf(wf);
		const auto T = randomPose(rng);
		for (size_t i = 0; i < fs.size(); ++i)
			for (size_t j = 0; j < fs.size(); ++j)
			{
				if (i == j) continue;
				const auto m = relateModel(fs[i], fs[j]);
				EXPECT_TRUE(
				    consistent(m, fs[i], fs[j], fs[i].transformed(T), fs[j].transformed(T), tiny))
				    << wf.name << " " << i << " " << j;
			}
	}
}

// A fragment of a line is still consistent with the model pair, a line moved by more than the
// tolerance is not, and a mirror image (h changes sign) is not.
TEST(PairRelation, FragmentsPassMovedAndMirroredFail)
{
	const auto a = line({0, 0, 0}, {100, 0, 0});
	const auto b = line({30, -20, 10}, {30, 40, 10});
	const auto m = relateModel(a, b);
	const Tolerance tol{2, 1 * M_PI / 180};
	EXPECT_TRUE(consistent(m, a, b, line({10, 0, 0}, {60, 0, 0}), b, tol));
	EXPECT_TRUE(consistent(m, a, b, a, line({30, 0, 10}, {30, 25, 10}), tol));
	EXPECT_FALSE(consistent(m, a, b, a, line({30, -20, 20}, {30, 40, 20}), tol));
	EXPECT_FALSE(consistent(m, a, b, a, line({30, -20, -10}, {30, 40, -10}), tol));
	EXPECT_FALSE(consistent(m, a, b, line({0, 0, 0}, {160, 0, 0}), b, tol));  // longer than model
}

// Flipping a scene line changes the orientation the matcher must hypothesise.
TEST(PairRelation, OrientationMatters)
{
	const auto a = line({0, 0, 0}, {100, 0, 0});
	const auto b = line({30, -20, 10}, {80, 40, 10});
	const auto m = relateModel(a, b);
	const Tolerance tol{2, 1 * M_PI / 180};
	EXPECT_TRUE(consistent(m, a, b, a, b, tol));
	EXPECT_FALSE(consistent(m, a, b, a, b.flipped(), tol));
	// Both flipped = the pair turned 180° about its common perpendicular: the segments then lie on
	// the other sides of the closest points, which these off-centre segments do not.
	EXPECT_FALSE(consistent(m, a, b, a.flipped(), b.flipped(), tol));
}

// Model tables: automatic cliques when the model has none, the model's own cliques otherwise,
// unknown ids rejected.
TEST(ModelTable, CliquesAutomaticOrFromTheModel)
{
	auto cube = makeAlphabetCube();
	const ModelTable automatic(cube, 5, 6);
	EXPECT_TRUE(automatic.cliquesAreAutomatic());
	ASSERT_EQ(automatic.cliques().size(), 5u);
	for (const auto& c : automatic.cliques())
	{
		EXPECT_EQ(c.members.size(), 5u);
		for (size_t m : c.members) EXPECT_NE(m, c.focus);
	}
	cube.cliques.push_back({1, {1, 2, 3}});
	const ModelTable own(cube, 5, 6);
	EXPECT_FALSE(own.cliquesAreAutomatic());
	ASSERT_EQ(own.cliques().size(), 1u);
	EXPECT_EQ(own.cliques()[0].members.size(), 2u);  // focus listed among members is dropped
	cube.cliques.push_back({1, {999}});
	EXPECT_THROW(ModelTable(cube, 5, 6), std::invalid_argument);
}

// Malformed models are rejected with a message naming the element.
TEST(ModelTable, DegenerateElementsRejected)
{
	mrolr::model::WireFrame wf;
	wf.name = "bad";
	wf.lines.push_back({4, {0, 0, 0}, {0, 0, 0}});
	wf.lines.push_back({5, {0, 0, 0}, {1, 0, 0}});
	try
	{
		ModelTable t(wf, 3, 3);
		FAIL() << "zero-length line accepted";
	}
	catch (const std::invalid_argument& e)
	{
		EXPECT_NE(std::string(e.what()).find("line 4"), std::string::npos) << e.what();
	}
	wf.lines.erase(wf.lines.begin());
	EXPECT_THROW(ModelTable(wf, 3, 3), std::invalid_argument);  // a single feature
	mrolr::model::Conic3 c;
	c.id = 9;
	c.a = -1;
	c.b = 1;
	c.t2 = 1;
	wf.conics.push_back(c);
	EXPECT_THROW(ModelTable(wf, 3, 3), std::invalid_argument);
	wf.conics[0].a = 1;
	wf.conics[0].centre.x() = std::nan("");
	EXPECT_THROW(ModelTable(wf, 3, 3), std::invalid_argument);
}
