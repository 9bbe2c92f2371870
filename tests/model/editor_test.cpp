#include <mrolr/model/AutoCliques.h>
#include <mrolr/model/ModelEditor.h>
#include <mrolr/model/ModelStats.h>
#include <mrolr/model/WireFrameSampling.h>

#include <gtest/gtest.h>

using namespace mrolr::model;

namespace
{
Conic3 circle(int id, const Eigen::Vector3d& c, double r, double t1, double t2)
{
	Conic3 k;
	k.id = id;
	k.centre = c;
	k.a = k.b = r;
	k.t1 = t1;
	k.t2 = t2;
	return k;
}

/** A 100 mm cube's 12 edges, ids 1..12, z up from 0. */
WireFrame cube()
{
	WireFrame wf;
	auto c = [](int i)
	{ return Eigen::Vector3d(i & 1 ? 50 : -50, i & 2 ? 50 : -50, i & 4 ? 100 : 0); };
	for (int i = 0; i < 8; ++i)
		for (int bit : {1, 2, 4})
			if (!(i & bit))
				wf.lines.push_back({static_cast<int>(wf.lines.size()) + 1, c(i), c(i | bit)});
	return wf;
}
}  // namespace

TEST(ModelEditor, MergesOverlappingCollinearLinesButNotParallelNeighbours)
{
	WireFrame wf;
	wf.lines = {{1, {0, 0, 0}, {60, 0, 0}},
	            {2, {40, 1, 0}, {100, 1, 0}},
	            {3, {0, 20, 0}, {100, 20, 0}},
	            {4, {101.5, 0.5, 0}, {130, 0.5, 0}}};
	EXPECT_EQ(mergeDuplicates(wf), 2u);
	ASSERT_EQ(wf.lines.size(), 2u);
	EXPECT_NEAR(wf.lines[0].length(), 130, 1.0);
	EXPECT_NEAR(wf.lines[1].p1.y(), 20, 1e-9);
}

TEST(ModelEditor, MergesConcentricArcsIntoTheirUnion)
{
	WireFrame wf;
	wf.conics = {circle(1, {0, 0, 0}, 40, 0, 2), circle(2, {1, 0, 0}, 41, 1.5, 4),
	             circle(3, {0, 0, 50}, 40, 0, 6)};
	EXPECT_EQ(mergeDuplicates(wf), 1u);
	ASSERT_EQ(wf.conics.size(), 2u);
	EXPECT_NEAR(wf.conics[0].t2 - wf.conics[0].t1, 4.0, 0.05);
}

TEST(ModelEditor, RemoveAddAndGraspKeepIdsUniqueAndCliquesValid)
{
	WireFrame wf = cube();
	wf.cliques.push_back({1, {2, 3, 1}});
	wf.cliques.push_back({5, {6, 5}});
	EXPECT_EQ(removeIds(wf, {3}), 1u);
	EXPECT_EQ(wf.cliques.size(), 1u);  // the clique naming 3 went with it
	EXPECT_THROW(removeIds(wf, {99}), std::invalid_argument);
	EXPECT_EQ(removeInBox(wf, {-60, -60, 90}, {60, 60, 110}), 4u);  // the top square
	const int next = maxId(wf) + 1;
	EXPECT_EQ(addLine(wf, {0, 0, 0}, {0, 0, 10}), next);
	EXPECT_THROW(addLine(wf, {1, 1, 1}, {1, 1, 1}), std::invalid_argument);
	Conic3 bad = circle(0, {0, 0, 0}, 10, 0, 1);
	bad.major = {0, 0, 1};
	EXPECT_THROW(addConic(wf, bad), std::invalid_argument);
	EXPECT_EQ(addConic(wf, circle(0, {0, 0, 0}, 10, 0, 1)), next + 1);
	setGrasp(wf, {0, 0, 50}, 90, 0, 0);
	EXPECT_TRUE(wf.has_grasp);
}

TEST(AutoCliques, CoverEveryViewingDirectionOfACube)
{
	WireFrame wf = cube();
	CliqueOptions o;
	EXPECT_EQ(uncoveredDirections(wf, o).size(), viewingDirections(o).size());
	const int added = addAutomaticCliques(wf, o);
	EXPECT_GT(added, 0);
	EXPECT_LE(static_cast<int>(wf.cliques.size()), o.max_cliques);
	EXPECT_TRUE(uncoveredDirections(wf, o).empty());
	for (const auto& c : wf.cliques)
	{
		EXPECT_EQ(static_cast<int>(c.members.size()), o.clique_size);
		EXPECT_EQ(c.members.back(), c.focus);  // as fig 7.1.12
	}
	const size_t before = wf.cliques.size();
	EXPECT_EQ(addAutomaticCliques(wf, o), 0);  // already covered: manual/earlier cliques kept
	EXPECT_EQ(wf.cliques.size(), before);
}

TEST(ModelStats, PerfectPartialAndFalseModels)
{
	const WireFrame truth = cube();
	const ModelQuality same = compareToTruth(truth, truth);
	EXPECT_NEAR(same.recovered_fraction, 1.0, 1e-9);
	EXPECT_EQ(same.false_features, 0);
	EXPECT_NEAR(same.median_endpoint_error_mm, 0, 1e-9);

	WireFrame half = truth;
	half.lines.resize(6);
	half.lines[0].p1 += Eigen::Vector3d(0, -2, 0);         // one endpoint 2 mm outside the cube
	half.lines.push_back({50, {300, 0, 0}, {400, 0, 0}});  // far from everything
	half.conics.push_back(circle(51, {0, 0, 100}, 30, 0, 1));
	const ModelQuality q = compareToTruth(half, truth);
	EXPECT_NEAR(q.recovered_fraction, 0.5, 0.03);
	EXPECT_EQ(q.false_features, 2);
	EXPECT_NEAR(q.max_endpoint_error_mm, 2.0, 0.2);
	EXPECT_NEAR(totalLength(truth), 1200, 1e-9);
}

TEST(ModelStats, RecoveryPerFeatureAddsUpToTheTotal)
{
	WireFrame truth = cube();
	truth.conics.push_back(circle(40, {0, 0, 200}, 30, 0, 2 * M_PI));
	WireFrame model = truth;
	model.lines.resize(3);
	model.lines[0].p2 = 0.5 * (model.lines[0].p1 + model.lines[0].p2);  // half of the first edge
	model.conics.clear();
	const auto per = recoveryPerFeature(model, truth);
	ASSERT_EQ(per.size(), truth.lines.size() + 1);
	EXPECT_NEAR(per[0].length_mm, 100, 2.5);
	EXPECT_NEAR(per[0].recovered_mm, 50, 6);  // within tol_mm of the half's end counts too
	EXPECT_NEAR(per[1].recovered_mm, per[1].length_mm, 1e-9);
	EXPECT_NEAR(per[5].recovered_mm, 0, 1e-9);
	EXPECT_TRUE(per.back().conic);
	EXPECT_EQ(per.back().id, 40);
	EXPECT_NEAR(per.back().recovered_mm, 0, 1e-9);
	EXPECT_NEAR(per.back().mid.z(), 200, 1e-6);  // the middle of a whole circle is its centre
	EXPECT_NEAR(per.back().length_mm, 2 * M_PI * 30, 1.0);
	double len = 0, rec = 0;
	for (const auto& f : per) len += f.length_mm, rec += f.recovered_mm;
	const auto q = compareToTruth(model, truth);
	EXPECT_NEAR(len, q.true_length_mm, 1e-6);
	EXPECT_NEAR(rec, q.recovered_length_mm, 1e-6);
}
