// occludersOf (MutualOcclusion.h): the found results other than the one searched become
// occluders at their poses; mismatched input is reported.
#include <mrolr/recog/images/MutualOcclusion.h>
#include <mrolr/sim/SyntheticObjects.h>
#include <mrolr/util/Cli.h>

#include <gtest/gtest.h>
#include <mrpt/config/CConfigFile.h>

using namespace mrolr::recog;
using namespace mrolr::sim;

namespace
{
RecognitionOptions shippedOptions()
{
	RecognitionOptions o;
	o.loadFromConfigFile(
	    mrpt::config::CConfigFile(mrolr::util::requireProjectFile("config/recognition.ini")),
	    "recognition");
	return o;
}
}  // namespace

TEST(MutualOcclusion, FoundResultsOtherThanTheSkippedOneBecomeOccluders)
{
	const auto objects = makeLabObjects();
	ASSERT_GE(objects.size(), 3u);
	const RecognitionOptions o = shippedOptions();
	const Recognizer a(objects[0], o), b(objects[1], o), c(objects[2], o);
	std::vector<RecognitionResult> r(3);
	r[0].found = true,
	r[0].T_OinS = Eigen::Translation3d(1, 2, 600) * Eigen::Isometry3d::Identity();
	r[1].found = false;
	r[2].found = true,
	r[2].T_OinS = Eigen::Translation3d(-50, 0, 700) * Eigen::Isometry3d::Identity();
	const auto occ = occludersOf({&a, &b, &c}, r, 2, 3.0);
	ASSERT_EQ(occ.size(), 1u);  // b not found, c skipped
	EXPECT_TRUE(occ[0].T_OinL.isApprox(r[0].T_OinS));
	EXPECT_EQ(occ[0].samples_O.size(), a.edgeSamples(3.0).size());
	EXPECT_EQ(occ[0].occ, &a.selfOcclusion());
	EXPECT_EQ(occludersOf({&a, &b, &c}, r, 1, 3.0).size(), 2u);
}

TEST(MutualOcclusion, MismatchedSizesAreReported)
{
	const auto objects = makeLabObjects();
	const Recognizer a(objects[0], shippedOptions());
	EXPECT_THROW(occludersOf({&a}, std::vector<RecognitionResult>(2), 0, 3.0),
	             std::invalid_argument);
}

// A solid contains the points inside it, not those beside it.
TEST(MutualOcclusion, ASolidContainsItsInsideOnly)
{
	const auto objects = makeLabObjects();
	const Recognizer a(objects[0], shippedOptions());
	const Eigen::Vector3d c = centroidOf(a.edgeSamples(3.0));
	EXPECT_TRUE(a.selfOcclusion().contains(c));
	EXPECT_FALSE(a.selfOcclusion().contains(c + Eigen::Vector3d(500, 0, 0)));
}

// A model found behind others must stand beside them: placed in a found object it interpenetrates,
// placed 300 mm to the side it does not.
TEST(MutualOcclusion, APoseInsideAFoundObjectInterpenetrates)
{
	const auto objects = makeLabObjects();
	const RecognitionOptions o = shippedOptions();
	const Recognizer a(objects[0], o), b(objects[1], o);
	std::vector<RecognitionResult> r(2);
	r[0].found = true,
	r[0].T_OinS = Eigen::Translation3d(0, 0, 700) * Eigen::Isometry3d::Identity();
	const auto occ = occludersOf({&a, &b}, r, 1, 3.0);
	ASSERT_EQ(occ.size(), 1u);
	const Eigen::Isometry3d inside =
	    r[0].T_OinS *
	    Eigen::Translation3d(centroidOf(occ[0].samples_O) - centroidOf(b.edgeSamples(3.0)));
	EXPECT_TRUE(interpenetrates(b, inside, occ));
	EXPECT_FALSE(interpenetrates(b, Eigen::Translation3d(300, 0, 0) * inside, occ));
	EXPECT_FALSE(interpenetrates(b, inside, {}));
}
