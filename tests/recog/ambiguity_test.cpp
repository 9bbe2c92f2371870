// A nearly symmetric box whose telling face is hidden is reported ambiguous, with both poses and
// their support; seen whole, or as a truly symmetric plain box, it is not.
#include <mrolr/recog/Recognizer.h>
#include <mrolr/sim/SyntheticScene.h>
#include <mrolr/recog/WireFrameBuilder.h>

#include <gtest/gtest.h>

using namespace mrolr::recog;
using namespace mrolr::sim;
using V = Eigen::Vector3d;

namespace
{
/** A 120 × 60 × 40 mm box; with @p label, a 40 × 25 mm rectangle printed on its +x end. */
mrolr::model::WireFrame box(bool label)
{
	WireFrameBuilder b(label ? "labelled_box" : "plain_box");
	b.box({-60, -30, 0}, {60, 30, 40});
	if (label) b.polyline({{60, -20, 8}, {60, 20, 8}, {60, 20, 33}, {60, -20, 33}}, true);
	return b.build();
}

double turnDeg(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b)
{
	return Eigen::AngleAxisd(a.linear().transpose() * b.linear()).angle() * 180.0 / M_PI;
}

const Eigen::Isometry3d kPose = tablePose(30, 25, V(20, -80, 700));
}  // namespace

TEST(Ambiguity, ABoxWhoseLabelIsHiddenIsAmbiguousWithBothPoses)
{
	const Recognizer rec(box(true), RecognitionOptions::defaults());
	const auto r = rec.recognize(placeInScene(box(false), kPose));  // the label not seen
	ASSERT_TRUE(r.found);
	EXPECT_TRUE(r.ambiguous);
	ASSERT_GE(r.poses.size(), 2u);
	EXPECT_TRUE(r.poses.front().T_OinS.isApprox(r.T_OinS));
	bool true_pose = false, turned = false;
	for (const auto& p : r.poses)
	{
		true_pose = true_pose || turnDeg(p.T_OinS, kPose) < 2;
		turned = turned || std::abs(turnDeg(p.T_OinS, kPose) - 180) < 2;
		EXPECT_GE(p.support, 0.95 * r.poses.front().support);
	}
	EXPECT_TRUE(true_pose) << "the true pose is among the answers";
	EXPECT_TRUE(turned) << "so is the box turned 180 deg about its vertical";
}

TEST(Ambiguity, SeenWholeOrTrulySymmetricItIsNot)
{
	const auto opts = RecognitionOptions::defaults();
	const auto whole = Recognizer(box(true), opts).recognize(placeInScene(box(true), kPose));
	ASSERT_TRUE(whole.found);
	EXPECT_FALSE(whole.ambiguous) << "the label tells the ends apart";
	EXPECT_TRUE(whole.poses.empty());
	EXPECT_LT(turnDeg(whole.T_OinS, kPose), 1.0);
	const auto plain = Recognizer(box(false), opts).recognize(placeInScene(box(false), kPose));
	ASSERT_TRUE(plain.found);
	EXPECT_FALSE(plain.ambiguous) << "a turn that maps the model onto itself is a symmetry";
}
